// One hit's product distribution env x (BRDF x cos) over a window, refined below its leaves
// (render/sampling/product/env_product_sampler.h is the CPU side). The GPU forms the product
// DENSE in private memory (architecture.md §4, the dense path): the bin's env factor (a truncated
// Haar image, env_product_tables.glsl) is synthesised to its 2^m x 2^m scaling coefficients,
// m <= WAVELIT_MAX_PRODUCT_LEVEL (2^4: the per-hit cost is (2^m + 1)^2 BRDF evaluations, and
// below the leaves the env's quadtree refines anyway), each leaf's average times BRDF x cos
// env-weighted over its 2 x 2 sub-cells (interpolated from the leaf's corners); sampling descends
// that pyramid, the lobe refinement, then the env's quadtree, and the pdf re-walks the same
// descent (dsDescendProduct).
#ifndef WAVELIT_ENV_PRODUCT_SAMPLER_GLSL
#define WAVELIT_ENV_PRODUCT_SAMPLER_GLSL

#include "common/constants.glsl"
#include "common/octahedral.glsl"
#include "sampling/sampler_environment.glsl"
#include "sampling/product/env_product_tables.glsl"

// The product pyramid of one hit: masses of levels 0..m at offsets (4^l - 1) / 3, and while it is
// decoded, the env factor's node of each cell of levels 0..m-1. The oracle's (oracle_sampler.glsl)
// is finer, WAVELIT_ORACLE_LEVEL; only its pipeline defines WAVELIT_ORACLE_SAMPLER.
int pyramidOffset(int l) { return ((1 << (2 * l)) - 1) / 3; }
#ifdef WAVELIT_ORACLE_SAMPLER
const int kPyramidLevel = WAVELIT_ORACLE_LEVEL;
#else
const int kPyramidLevel = WAVELIT_MAX_PRODUCT_LEVEL;
#endif
float gMass[((1 << (2 * (kPyramidLevel + 1))) - 1) / 3];
int gNode[((1 << (2 * WAVELIT_MAX_PRODUCT_LEVEL)) - 1) / 3];

// massOffset at or below this: the pyramid lies in the per-pixel product cache at word
// kMassInProductCache - massOffset (sampling/product_cache.glsl).
const int kMassInProductCache = -2;

// Cell i of the hit's pyramid: the pixel's cached one (the camera vertex, product_cache.glsl) or
// the private one.
float dsMass(DirSampler s, int i) {
#ifdef WAVELIT_PRODUCT_CACHE_BINDING
    if (s.massOffset <= kMassInProductCache) {
        // Through the u64 view, as the entry was written (product_cache.glsl).
        uint j = uint(kMassInProductCache - s.massOffset + i);
        uvec2 w = unpackUint2x32(productCache64[j >> 1u]);
        return uintBitsToFloat((j & 1u) != 0u ? w.y : w.x);
    }
#endif
    return gMass[i];
}

// Sums the leaves (level m) of gMass up to its root; returns the total.
float dsSumPyramid(int m) {
    for (int l = m - 1; l >= 0; --l) {
        int sideL = 1 << l, offL = pyramidOffset(l), offC = pyramidOffset(l + 1);
        for (int y = 0; y < sideL; ++y)
            for (int x = 0; x < sideL; ++x) {
                int c0 = offC + 2 * y * (2 * sideL) + 2 * x, c1 = c0 + 2 * sideL;
                gMass[offL + y * sideL + x] = gMass[c0] + gMass[c0 + 1] + gMass[c1] + gMass[c1 + 1];
            }
    }
    return gMass[0];
}

// BRDF x cos at the centres of the four sub-cells of global cell (l, x, y), weighted by the env's
// luminance there: sum_s L_s f(c_s) / sum_s L_s (the plain mean where the env is black). Times
// the env's average over the cell this is the mean of L f over the sub-cells, so a sun in the
// steep flank of a lobe gets the BRDF where it sits, not at the cell's centre (the CPU's
// windowTabulateEnvWeighted). `sub`: the env's shares in the sub-cells (envSubCellMasses).
float dsEnvWeightedBrdfCos(DirSampler s, int l, int x, int y, double sub[4]) {
    double side = 1.0LF / double(1 << (l + 1));
    double weighted = 0.0LF, weight = 0.0LF, plain = 0.0LF;
    for (int c = 0; c < 4; ++c) {
        dvec2 centre = (dvec2(2 * x + (c & 1), 2 * y + (c >> 1)) + 0.5LF) * side;
        double f = double(dsBrdfCos(s, envToWorld(s.cosSinYaw, octToDirection(vec2(centre)))));
        weighted += sub[c] * f;
        weight += sub[c];
        plain += f;
    }
    return float(weight > 0.0LF ? weighted / weight : 0.25LF * plain);
}

// The wavelet's leaf corners along one row: f cos at the global corner points (gx0 + i, gy) / 2^l,
// i = 0..side, of the octahedral domain (row's entries past side are not written).
const int kCornerRowLength = (1 << WAVELIT_MAX_PRODUCT_LEVEL) + 1;
void dsCornerRow(DirSampler s, int l, int gx0, int gy, int side,
                 inout float row[kCornerRowLength]) {
    double cell = 1.0LF / double(1 << l);
    for (int i = 0; i <= side; ++i) {
        vec3 corner = octToDirection(vec2(dvec2(gx0 + i, gy) * cell));
        row[i] = dsBrdfCos(s, envToWorld(s.cosSinYaw, corner));
    }
}

// BRDF x cos of the wavelet's leaf (l, x, y) env-weighted over its four sub-cells, as
// dsEnvWeightedBrdfCos, but with f cos at each sub-cell centre interpolated bilinearly from the
// leaf's corners (`corner`: (x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)), which neighbouring
// leaves share: (2^m + 1)^2 BRDF evaluations a product instead of 4^(m + 1), the cache build's
// main cost (docs/performance.md "Wavelet pass cost, round 7"; the CPU's
// windowTabulateEnvWeightedCornersBatch). A leaf whose corners all see f cos = 0 is 0 (below the
// horizon: about half of a whole-sphere window's leaves) and skips the env's split. The split
// comes from the cell's node alone, since the cell's mass cancels in the weighted mean (the env is
// floored above 0, so the mass is never 0). The cell's node is envFindNode's, found from its
// parent's: `parent` (the env node of cell (l - 1, parentCell), at level parentReached, with its
// firstChild) is looked up when a call needs it and parentCell is not (x / 2, y / 2) (parent < 0:
// none yet), and kept for the next calls: one walk from the root per 2 x 2 sibling leaves, not
// one per leaf (each step a word load on lavapipe).
float dsLeafBrdfCos(int l, int x, int y, float corner[4], inout int parent,
                    inout ivec2 parentCell, inout int parentReached, inout int parentFirstChild) {
    if (!(corner[0] > 0.0 || corner[1] > 0.0 || corner[2] > 0.0 || corner[3] > 0.0)) return 0.0;
    double f[4];
    for (int c = 0; c < 4; ++c) {
        double u = (c & 1) != 0 ? 0.75LF : 0.25LF, v = (c >> 1) != 0 ? 0.75LF : 0.25LF;
        f[c] = (1.0LF - u) * (1.0LF - v) * double(corner[0]) + u * (1.0LF - v) * double(corner[1]) +
               (1.0LF - u) * v * double(corner[2]) + u * v * double(corner[3]);
    }
    if (parent < 0 || parentCell != ivec2(x >> 1, y >> 1)) {
        parentCell = ivec2(x >> 1, y >> 1);
        parent = envFindNode(l - 1, parentCell.x, parentCell.y, parentReached);
        parentFirstChild = parentReached == l - 1 ? envNodes[parent].firstChild : -1;
    }
    // envFindNode(l, x, y): one step below the parent where the tree goes on.
    int node = parentFirstChild >= 0 ? parentFirstChild + (x & 1) + 2 * (y & 1) : parent;
    int reached = parentFirstChild >= 0 ? l : parentReached;
    double w[4] = double[4](0.25LF, 0.25LF, 0.25LF, 0.25LF);
    if (reached == l) envChildShares(node, w);
    double weighted = 0.0LF, weight = 0.0LF;
    for (int c = 0; c < 4; ++c) {
        weighted += w[c] * f[c];
        weight += w[c];
    }
    return float(weighted / weight);
}

// Decodes the env factor `factor` (truncated Haar, SparseHaar's tree) to scaling coefficients at
// level m (haar.h's synthesis), multiplies each cell's average by the env-weighted BRDF x cos over
// its sub-cells, and sums the masses up. Returns the total mass (0: nothing to sample).
float dsBuildProduct(DirSampler s, SamplerMaterial sm, uint factor) {
    uint firstNode, nodeCount;
    flatFactorNodes(sm, factor, firstNode, nodeCount);
    int m = s.m;
    gMass[0] = flatScaling(sm, factor);
    gNode[0] = nodeCount > 0u ? 0 : -1;
    for (int l = 0; l < m; ++l) {
        int side = 1 << l, off = pyramidOffset(l), offChild = pyramidOffset(l + 1);
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                float sc = gMass[off + y * side + x];
                int node = gNode[off + y * side + x];
                vec3 d = vec3(0.0);
                ivec4 children = ivec4(-1);
                if (node >= 0) {
                    uint base = flatNodeBase(sm, firstNode, node);
                    d = flatNodeDetails(base);
                    if (l + 1 < m) children = flatNodeChildren(base);
                }
                float child[4] = float[4](0.5 * (sc + d.x + d.y + d.z), 0.5 * (sc - d.x + d.y - d.z),
                                          0.5 * (sc + d.x - d.y - d.z), 0.5 * (sc - d.x - d.y + d.z));
                for (int c = 0; c < 4; ++c) {
                    int i = offChild + (2 * y + (c >> 1)) * (2 * side) + 2 * x + (c & 1);
                    gMass[i] = child[c];
                    if (l + 1 < m) gNode[i] = children[c];
                }
            }
    }
    // Leaves: average env luminance (2^m x the scaling coefficient), clamped at 0 (truncation
    // leaves negatives), times BRDF x cos env-weighted over the leaf's four sub-cells
    // (dsLeafBrdfCos). Visited by 2 x 2 blocks, which are sibling leaves sharing their parent's
    // env node when m >= 2 (the window's origin (ox, oy) << (m - 1) is then even), a block row at
    // a time: the corners' f cos of its three rows, the first the row above's last.
    int side = 1 << m, off = pyramidOffset(m), l = s.k + m;
    int gx0 = s.ox << (m - 1), gy0 = s.oy << (m - 1);
    float rows[3][kCornerRowLength];
    dsCornerRow(s, l, gx0, gy0, side, rows[0]);
    for (int by = 0; by < side; by += 2) {
        dsCornerRow(s, l, gx0, gy0 + by + 1, side, rows[1]);
        dsCornerRow(s, l, gx0, gy0 + by + 2, side, rows[2]);
        for (int bx = 0; bx < side; bx += 2) {
            int parent = -1, parentReached = 0, parentFirstChild = -1;
            ivec2 parentCell = ivec2(0);
            for (int c = 0; c < 4; ++c) {
                int x = bx + (c & 1), y = by + (c >> 1), r = c >> 1;
                float e = max(0.0, gMass[off + y * side + x] * float(side));
                float corner[4] = float[4](rows[r][x], rows[r][x + 1], rows[r + 1][x],
                                           rows[r + 1][x + 1]);
                gMass[off + y * side + x] =
                    e > 0.0 ? e * dsLeafBrdfCos(l, gx0 + x, gy0 + y, corner, parent, parentCell,
                                                parentReached, parentFirstChild)
                            : 0.0;
            }
        }
        rows[0] = rows[2];
    }
    return dsSumPyramid(m);
}

// Each of two parts' own share of their sum (1/2 each when both are empty).
void dsParts(double a, double b, out double p0, out double p1) {
    double whole = a + b;
    p0 = whole > 0.0LF ? a / whole : 0.5LF;
    p1 = whole > 0.0LF ? b / whole : 0.5LF;
}

// Probabilities of the rows below pyramid cell (l, x, y) and of the columns given each row: in
// double from the float masses, each half its own share (1 - p would lose a sun's 1e-6).
void dsChildProbabilities(DirSampler s, int l, int x, int y, out double pRow[2],
                          out double pColumn[4]) {
    int side = 1 << (l + 1), off = pyramidOffset(l + 1);
    int c0 = off + 2 * y * side + 2 * x, c1 = c0 + side;
    double a, b, c, d;
#ifdef WAVELIT_PRODUCT_CACHE_BINDING
    if (s.massOffset <= kMassInProductCache) {
        // The pixel's cached pyramid starts at an odd word (product_cache.h kPyramidAt): siblings
        // c0, c0 + 1 (and c1, c1 + 1) share an 8-byte aligned u64, one load each pair.
        uint at = uint(kMassInProductCache - s.massOffset);
        vec2 ab = uintBitsToFloat(unpackUint2x32(productCache64[(at + uint(c0)) >> 1u]));
        vec2 cd = uintBitsToFloat(unpackUint2x32(productCache64[(at + uint(c1)) >> 1u]));
        a = ab.x;
        b = ab.y;
        c = cd.x;
        d = cd.y;
    } else
#endif
    {
        a = dsMass(s, c0);
        b = dsMass(s, c0 + 1);
        c = dsMass(s, c1);
        d = dsMass(s, c1 + 1);
    }
    dsParts(a + b, c + d, pRow[0], pRow[1]);
    dsParts(a, b, pColumn[0], pColumn[1]);
    dsParts(c, d, pColumn[2], pColumn[3]);
}

// Lobe refinement below the product's leaves (EnvProductSampler's): the four children of a cell
// are weighted by the env's own split of the cell (its quadtree's conditional probabilities)
// times BRDF x cos at the child's centre, plus WAVELIT_LOBE_FLOOR of the largest so no child with
// env light loses support. The weights depend only on the cell, so the pdf's walk is exact.
// `node`, `reached`: envFindNode's answer for the cell. Returns the cell's node's firstChild
// (-1: the tree is constant below the cell, or above it).
int dsRefineWeights(DirSampler s, int l, int x, int y, int node, int reached, out double w[4]) {
    w = double[4](0.25LF, 0.25LF, 0.25LF, 0.25LF);
    int firstChild = -1;
    if (reached == l) firstChild = envChildSharesAndFirst(node, w);
    double side = 1.0LF / double(1 << (l + 1));
    float h[4];
    float hmax = 0.0;
    for (int c = 0; c < 4; ++c) {
        dvec2 centre = (dvec2(2 * x + (c & 1), 2 * y + (c >> 1)) + 0.5LF) * side;
        h[c] = dsBrdfCos(s, envToWorld(s.cosSinYaw, octToDirection(vec2(centre))));
        hmax = max(hmax, h[c]);
    }
    if (hmax > 0.0 && !isinf(hmax))
        for (int c = 0; c < 4; ++c) w[c] *= double(h[c] + WAVELIT_LOBE_FLOOR * hmax);
    return firstChild;
}

// lobeRefineLevels (env_product_tables.h): levels below leaf level `leafLevel` until a cell is
// narrower than the material's refineCellAngle, at most refineMaxLevels, never below the env.
int dsRefineLevels(SamplerMaterial sm, int leafLevel, int envLevel) {
    if (!(sm.refineCellAngle > 0.0)) return 0;
    float cell = sqrt(kFourPi) / float(1 << leafLevel);
    int levels = 0;
    while (levels < int(sm.refineMaxLevels) && leafLevel + levels < envLevel &&
           cell > sm.refineCellAngle) {
        cell *= 0.5;
        ++levels;
    }
    return levels;
}

// The product technique's one descent, serving both the draw and the pdf (takeShare): the
// product's pyramid to a leaf, the lobe refinement, then the env's quadtree, drawing by u or
// following square point p (which must lie in the window). Returns the probability of the cell
// reached, left in (l, x, y) (global).
double dsDescendProduct(DirSampler s, bool drawing, inout dvec2 u, dvec2 p, out int l, out int x,
                        out int y) {
    int shift = s.m - 1;
    // The leaf holding p, window-local (only read when following p).
    double scale = double(1 << (s.k + s.m));
    int lx = int(p.x * scale) - (s.ox << shift), ly = int(p.y * scale) - (s.oy << shift);
    double probability = 1.0LF;
    x = 0;
    y = 0;
    for (int level = 0; level < s.m; ++level) {
        double pRow[2], pColumn[4];
        dsChildProbabilities(s, level, x, y, pRow, pColumn);
        int bit = s.m - 1 - level;
        int cy = takeShare(drawing, pRow[0], pRow[1], (ly >> bit) & 1, u.y, probability);
        int cx = takeShare(drawing, pColumn[2 * cy], pColumn[2 * cy + 1], (lx >> bit) & 1, u.x,
                           probability);
        x = 2 * x + cx;
        y = 2 * y + cy;
    }
    l = s.k + s.m;
    x += s.ox << shift;
    y += s.oy << shift;
    if (!drawing && !(probability > 0.0LF)) return 0.0LF; // p is where nothing is drawn
    // The env tree's node of the cell, carried down the refinement (one walk from the root).
    int reached;
    int node = envFindNode(l, x, y, reached);
    for (int r = 0; r < s.refineLevels; ++r) {
        double w[4], p0, p1;
        int firstChild = dsRefineWeights(s, l, x, y, node, reached, w);
        dsParts(w[0] + w[1], w[2] + w[3], p0, p1);
        int cy = takeShare(drawing, p0, p1, childHolding(drawing, p.y, l, y), u.y, probability);
        dsParts(w[2 * cy], w[2 * cy + 1], p0, p1);
        int cx = takeShare(drawing, p0, p1, childHolding(drawing, p.x, l, x), u.x, probability);
        if (firstChild >= 0) { // reached == l and the tree goes on below the cell
            node = firstChild + cx + 2 * cy;
            reached = l + 1;
        }
        l += 1;
        x = 2 * x + cx;
        y = 2 * y + cy;
    }
    if (!drawing && !(probability > 0.0LF)) return 0.0LF;
    return probability * envDescendFrom(drawing, u, p, l, x, y, node, reached);
}

// A point of the octahedral square from the product; `density` per unit square area.
dvec2 dsSampleProduct(DirSampler s, dvec2 u, out double density) {
    int l, x, y;
    density = dsDescendProduct(s, true, u, dvec2(0.0LF), l, x, y) * powerOfFour(l);
    return (dvec2(x, y) + u) / double(1 << l);
}

// The product technique's density at square point p (0 outside its window).
double dsProductPdf(DirSampler s, dvec2 p) {
    int shift = s.m - 1, side = 1 << s.m;
    double scale = double(1 << (s.k + s.m));
    int lx = int(p.x * scale) - (s.ox << shift), ly = int(p.y * scale) - (s.oy << shift);
    if (lx < 0 || ly < 0 || lx >= side || ly >= side) return 0.0LF;
    dvec2 u = dvec2(0.0LF);
    int l, x, y;
    return dsDescendProduct(s, false, u, p, l, x, y) * powerOfFour(l);
}

#endif
