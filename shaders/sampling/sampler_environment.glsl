// The environment as the samplers see it (render/sampling/sampler_environment.h): its rotation,
// and its sampling quadtree, the twin of wavelet::HierarchicalSampler's descent over its float
// tables (renderer/wavelet/hierarchical_sampler.cpp; 16 bytes per node, see TableNode there).
// The including shader declares (EnvNode: sampling/sampler_structs.glsl)
//     buffer ... { EnvNode envNodes[]; };  buffer ... { u64vec2 envNodes64[]; };
// (the same buffer at the same binding: a whole node in two 64-bit loads instead of four 32-bit
// ones on lavapipe, docs/performance.md "Lavapipe throughput (issue 12)").
// Points and the numbers u are DOUBLE: a descent through 10+ levels rescales u by each choice's
// probability (a sun's texel takes 1e-6 of a split), and float would run out of digits, so the
// point drawn would no longer follow the tabulated pdf. Densities are per unit area of the
// octahedral square (divide by 4 pi for solid angle).
#ifndef WAVELIT_SAMPLER_ENVIRONMENT_GLSL
#define WAVELIT_SAMPLER_ENVIRONMENT_GLSL

const double kBelowOneD = 1.0LF - 1.0e-15LF;

vec3 envToLocal(vec2 cs, vec3 d) { return vec3(cs.x * d.x - cs.y * d.z, d.y, cs.y * d.x + cs.x * d.z); }
vec3 envToWorld(vec2 cs, vec3 d) { return vec3(cs.x * d.x + cs.y * d.z, d.y, -cs.y * d.x + cs.x * d.z); }

// A stored split: the smaller probability, its sign bit marking the second half.
void decodeSplit(float s, out double p0, out double p1) {
    if ((floatBitsToUint(s) >> 31) != 0u) {
        p1 = double(-s);
        p0 = 1.0LF - p1;
    } else {
        p0 = double(s);
        p1 = 1.0LF - p0;
    }
}

// Picks the first of two parts with probability p0 (else p1), rescaling u into [0, 1) and
// multiplying `probability` by the choice's. Callers pass each part's own share, so a part with
// 1e-6 of the mass keeps its digits (1 - p0 would not).
int chooseShare(double p0, double p1, inout double u, inout double probability) {
    if (u < p0) {
        u = min(u / p0, kBelowOneD);
        probability *= p0;
        return 0;
    }
    u = min((u - p0) / p1, kBelowOneD);
    probability *= p1;
    return 1;
}

// One step of a descent that serves both the draw and the pdf: drawing, the part is chosen by u
// (chooseShare); otherwise `part` (the one holding the point) is taken. Either way `probability`
// gets the part's share, so sample and pdf walk the same code.
int takeShare(bool drawing, double p0, double p1, int part, inout double u,
              inout double probability) {
    if (drawing) return chooseShare(p0, p1, u, probability);
    probability *= part == 0 ? p0 : p1;
    return part;
}

// Which child (0, 1) of cell index c at level l holds square coordinate t (0 when drawing: the
// draw does not read it).
int childHolding(bool drawing, double t, int l, int c) {
    return drawing ? 0 : clamp(int(t * double(1 << (l + 1))) - 2 * c, 0, 1);
}

// 4^l for l <= 31 (the oracle's sub-cells reach level 17: 1u << 2l would overflow).
double powerOfFour(int l) {
    double side = double(1u << uint(l));
    return side * side;
}

// Node i read through the u64 view: (py0, px0y0), (px0y1, firstChild), low word first.
EnvNode envNodeAt(int i) {
    u64vec2 q = envNodes64[i];
    uvec2 a = unpackUint2x32(q.x), b = unpackUint2x32(q.y);
    return EnvNode(uintBitsToFloat(a.x), uintBitsToFloat(a.y), uintBitsToFloat(b.x), int(b.y));
}

// The node of cell (l, x, y), or of its deepest ancestor where the tree is constant above it;
// `reached` is that node's level.
int envFindNode(int l, int x, int y, out int reached) {
    int node = 0;
    reached = 0;
    while (reached < l && envNodes[node].firstChild >= 0) {
        int shift = l - reached - 1;
        int c = ((x >> shift) & 1) | (((y >> shift) & 1) << 1);
        node = envNodes[node].firstChild + c;
        ++reached;
    }
    return node;
}

// envDescend (below) from a known node: `node` (at level `reached`) is cell (l, x, y)'s, or its deepest
// ancestor where the tree is constant above it (envFindNode's answer; a descent that walked down
// to the cell carries it instead of walking again from the root).
double envDescendFrom(bool drawing, inout dvec2 u, dvec2 p, inout int l, inout int x, inout int y,
                      int node, int reached) {
    double probability = 1.0LF;
    if (reached < l) return probability;
    for (EnvNode n = envNodeAt(node); n.firstChild >= 0; n = envNodeAt(node)) {
        double p0, p1;
        decodeSplit(n.py0, p0, p1);
        int cy = takeShare(drawing, p0, p1, childHolding(drawing, p.y, l, y), u.y, probability);
        decodeSplit(cy == 0 ? n.px0y0 : n.px0y1, p0, p1);
        int cx = takeShare(drawing, p0, p1, childHolding(drawing, p.x, l, x), u.x, probability);
        node = n.firstChild + cx + 2 * cy;
        l += 1;
        x = 2 * x + cx;
        y = 2 * y + cy;
    }
    return probability;
}

// The table's descent below cell (l, x, y), drawing by u or following point p (takeShare): row
// by u.y, then column by u.x given the row. Returns the probability of the leaf reached within
// the cell and leaves (l, x, y) at that leaf; where the tree is constant above the cell, the cell
// itself (probability 1).
double envDescend(bool drawing, inout dvec2 u, dvec2 p, inout int l, inout int x, inout int y) {
    int reached;
    int node = envFindNode(l, x, y, reached);
    return envDescendFrom(drawing, u, p, l, x, y, node, reached);
}

// Draws a point inside cell (l, x, y) from the table's conditional distribution there;
// `density` is the conditional density per unit square area (integrates to 1 over the cell).
dvec2 envSampleWithin(int l, int x, int y, dvec2 u, out double density) {
    double probability = envDescend(true, u, dvec2(0.0LF), l, x, y);
    density = probability * powerOfFour(l);
    return (dvec2(x, y) + u) / double(1 << l);
}

// The conditional density of envSampleWithin at point p (0 outside the cell).
double envPdfWithin(int l, int x, int y, dvec2 p) {
    dvec2 local = p * double(1 << l) - dvec2(x, y);
    if (local.x < 0.0LF || local.x >= 1.0LF || local.y < 0.0LF || local.y >= 1.0LF) return 0.0LF;
    dvec2 u = dvec2(0.0LF);
    double probability = envDescend(false, u, p, l, x, y);
    return probability * powerOfFour(l);
}

// The probabilities of a node's four children (in (x, y) order: 0 = (0,0), 1 = (1,0),
// 2 = (0,1), 3 = (1,1)), 1/4 each for a leaf of the tree; returns the node's firstChild (< 0: a
// leaf), read with the splits (a caller stepping down needs no second read).
int envChildSharesAndFirst(int node, out double w[4]) {
    w = double[4](0.25LF, 0.25LF, 0.25LF, 0.25LF);
    EnvNode n = envNodeAt(node);
    if (n.firstChild < 0) return n.firstChild;
    double py0, py1, pl0, pr0, pl1, pr1;
    decodeSplit(n.py0, py0, py1);
    decodeSplit(n.px0y0, pl0, pr0);
    decodeSplit(n.px0y1, pl1, pr1);
    w[0] = py0 * pl0;
    w[1] = py0 * pr0;
    w[2] = py1 * pl1;
    w[3] = py1 * pr1;
    return n.firstChild;
}

// envChildSharesAndFirst's shares; false for a leaf of the tree.
bool envChildShares(int node, out double w[4]) { return envChildSharesAndFirst(node, w) >= 0; }

// The env's share of its total luminance in cell (l, x, y), by its quadtree's splits (uniform
// below the tree's leaves); `node` is the cell's node when `exact`, else a leaf above the cell.
double envCellMass(int l, int x, int y, out int node, out bool exact) {
    node = 0;
    int reached = 0;
    double mass = 1.0LF;
    while (reached < l) {
        EnvNode n = envNodeAt(node);
        if (n.firstChild < 0) break;
        int shift = l - reached - 1;
        int cx = (x >> shift) & 1, cy = (y >> shift) & 1;
        double py0, py1, px0, px1;
        decodeSplit(n.py0, py0, py1);
        decodeSplit(cy == 0 ? n.px0y0 : n.px0y1, px0, px1);
        mass *= (cy == 0 ? py0 : py1) * (cx == 0 ? px0 : px1);
        node = n.firstChild + cx + 2 * cy;
        ++reached;
    }
    exact = reached == l;
    return mass / powerOfFour(l - reached);
}

// The env's shares of its luminance in the four sub-cells of cell (l, x, y).
void envSubCellMasses(int l, int x, int y, out double sub[4]) {
    int node;
    bool exact;
    double mass = envCellMass(l, x, y, node, exact);
    double w[4] = double[4](0.25LF, 0.25LF, 0.25LF, 0.25LF);
    if (exact) envChildShares(node, w);
    for (int c = 0; c < 4; ++c) sub[c] = mass * w[c];
}

#endif
