// The environment's sampling quadtree on the GPU: twin of wavelet::HierarchicalSampler's descent
// over its float tables (renderer/wavelet/hierarchical_sampler.cpp; 16 bytes per node, see
// TableNode there). The including shader declares (EnvNode: common/sampler_structs.glsl)
//     buffer ... { EnvNode envNodes[]; };
// Points and the numbers u are DOUBLE: a descent through 10+ levels rescales u by each choice's
// probability (a sun's texel takes 1e-6 of a split), and float would run out of digits, so the
// point drawn would no longer follow the tabulated pdf. Densities are per unit area of the
// octahedral square (divide by 4 pi for solid angle).
#ifndef WAVELIT_ENV_TABLE_GLSL
#define WAVELIT_ENV_TABLE_GLSL

const double kBelowOneD = 1.0LF - 1.0e-15LF;

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

// A stored split's choice.
int chooseHalf(float split, inout double u, inout double probability) {
    double p0, p1;
    decodeSplit(split, p0, p1);
    return chooseShare(p0, p1, u, probability);
}

// 4^l for l <= 31 (the oracle's sub-cells reach level 17: 1u << 2l would overflow).
double powerOfFour(int l) {
    double side = double(1u << uint(l));
    return side * side;
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

// Draws a point inside cell (l, x, y) from the table's conditional distribution there;
// `density` is the conditional density per unit square area (integrates to 1 over the cell).
dvec2 envSampleWithin(int l, int x, int y, dvec2 u, out double density) {
    int reached;
    int node = envFindNode(l, x, y, reached);
    if (reached < l) {
        density = powerOfFour(l);
        return (dvec2(x, y) + u) / double(1 << l);
    }
    double probability = 1.0LF;
    while (envNodes[node].firstChild >= 0) {
        EnvNode n = envNodes[node];
        int cy = chooseHalf(n.py0, u.y, probability);
        int cx = chooseHalf(cy == 0 ? n.px0y0 : n.px0y1, u.x, probability);
        node = n.firstChild + cx + 2 * cy;
        l += 1;
        x = 2 * x + cx;
        y = 2 * y + cy;
    }
    density = probability * powerOfFour(l);
    return (dvec2(x, y) + u) / double(1 << l);
}

// The conditional density of envSampleWithin at point p (0 outside the cell).
double envPdfWithin(int l, int x, int y, dvec2 p) {
    double scale = double(1 << l);
    dvec2 local = p * scale - dvec2(x, y);
    if (local.x < 0.0LF || local.x >= 1.0LF || local.y < 0.0LF || local.y >= 1.0LF) return 0.0LF;
    int reached;
    int node = envFindNode(l, x, y, reached);
    if (reached < l) return powerOfFour(l);
    double probability = 1.0LF;
    while (envNodes[node].firstChild >= 0) {
        EnvNode n = envNodes[node];
        double childScale = double(1 << (l + 1));
        int cx = clamp(int(p.x * childScale) - 2 * x, 0, 1);
        int cy = clamp(int(p.y * childScale) - 2 * y, 0, 1);
        double py0, py1, px0, px1;
        decodeSplit(n.py0, py0, py1);
        decodeSplit(cy == 0 ? n.px0y0 : n.px0y1, px0, px1);
        probability *= (cy == 0 ? py0 : py1) * (cx == 0 ? px0 : px1);
        node = n.firstChild + cx + 2 * cy;
        l += 1;
        x = 2 * x + cx;
        y = 2 * y + cy;
    }
    return probability * powerOfFour(l);
}

#endif
