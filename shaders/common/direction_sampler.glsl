// Direction samplers of the Vulkan tracer (issue 6; render/sampling/direction_sampler.h is the CPU side,
// docs/wavelet-sampler.md the tables). Every kind returns the exact solid-angle pdf of the
// mixture it draws from, and the tracer divides by it (architecture.md §4: never the paper's eq 7).
//
//   uniform, cosine, bsdf   hemisphere / plugin sampling, as on the CPU
//   env                     the environment's quadtree (env_table.glsl)
//   mis                     bsdf 1/2 + env 1/2
//   wavelet                 per hit: the env factor of the reflection direction's bin (a
//                           truncated Haar image over the bin's window, decoded to 2^m x 2^m)
//                           times BRDF x cos (env-weighted over 2 x 2 sub-cells): the quadtree, built
//                           dense in private memory (2^m <= 16, the dense path of architecture.md §4),
//                           refined below its leaves by the env's own quadtree (§4.1 item 1);
//                           mixed with bsdf (defensive) and env with the CPU's share rule.
//                           Lobes the env cannot resolve (policy BsdfLobe): bsdf + env.
//   oracle                  per hit: a DENSE product (env cell averages x BRDF x cos at 2 x 2
//                           sub-cells per leaf, 2^5 x 2^5 leaves) over a window fitted to the lobe
//                           around the exact axis (sampler_window.h's chooseWindow), refined by 2
//                           levels of the lobe refinement and then the env's quadtree; mixed as
//                           the CPU's oracle (bsdf 0.05, env share >= 0.02). Compiled with
//                           WAVELIT_ORACLE_SAMPLER (its private pyramid is 4x the wavelet's).
//
// The including shader includes common/sampler_structs.glsl and declares, before this file:
//   buffer { EnvNode envNodes[]; };  buffer { SamplerMaterial samplerMaterials[]; };
//   buffer { uint samplerWords[]; };
// samplerWords holds each material's flat product tables (MaterialProductTables::flatten(), its
// three arrays at the three offsets) and the env's 8 x 8 cell averages (float bits).
//
// Tabulated draws keep their double square point: the pdfs of BOTH tabulated techniques are
// evaluated at that point, never at the float direction re-mapped to the square, which can land
// in the neighbouring texel (a sun's texel is 1e6 x denser than the sky beside it).
#ifndef WAVELIT_DIRECTION_SAMPLER_GLSL
#define WAVELIT_DIRECTION_SAMPLER_GLSL

#include "common/brdf.glsl"
#include "common/constants.glsl"
#include "common/env_table.glsl"
#include "common/octahedral.glsl"
#include "common/sampling.glsl"

// Codes of render::SamplerKind (render_options.h), in its order.
const uint kSamplerUniform = 0u;
const uint kSamplerCosine = 1u;
const uint kSamplerBsdf = 2u;
const uint kSamplerEnv = 3u;
const uint kSamplerMis = 4u;
const uint kSamplerWavelet = 5u;
const uint kSamplerOracle = 6u;

// SamplerMaterial.mode (render/gpu/gpu_sampler_data.h).
const uint kModeBsdfOnly = 0u;
const uint kModeProduct = 1u;
const uint kModeBsdfLobe = 2u;
const uint kModeOracle = 3u;

// The mixture's constants. The CPU's minimum env share is 0.02 (each defensive share c costs ~c in
// Var/I^2 where the lobe technique is good); the GPU keeps 0.05: at 0.02 the glossy-sphere scene's
// per-sample MSE rose 18x (fireflies where the 16^2 truncated env factor misses bright env that
// only the env technique then covers; docs/wavelet-sampler.md).
const double kMinEnvShare = 0.05LF;
const double kMaxEnvShare = 0.8LF;
const int kLobeStrata = 4;
const int kTailLevel = 3; // 8 x 8 cells (the CPU uses 16 x 16): 64 BRDF evaluations per hit
const float kFourPi = 4.0 * kPi;

// The product pyramid of one hit: masses of levels 0..m at offsets (4^l - 1) / 3, and while it is
// decoded, the env factor's node of each cell of levels 0..m-1. The GPU stops at 2^4 x 2^4 leaves
// (render/gpu/gpu_sampler_data.h kGpuMaxProductLevel) even where the tables hold finer details: the
// per-hit cost is ~4^m BRDF evaluations, and below the leaves the env's quadtree refines anyway.
const int kMaxProductLevel = 4;
// The oracle's dense grid (render/gpu/gpu_sampler_data.h kGpuOracleLevel) and how far below the env's
// texels its window may shrink (OracleOptions::depthBelowEnv), and its smallest env share (the
// CPU oracle's).
const int kOracleLevel = 5;
const int kOracleDepthBelowEnv = 6;
const double kOracleMinEnvShare = 0.02LF;
#ifdef WAVELIT_ORACLE_SAMPLER
float gMass[1365]; // levels 0..5
#else
float gMass[341]; // levels 0..4
#endif
int gNode[85];

struct DirSampler {
    float cProduct, cBsdf, cEnv, cUniform, cCosine; // mixture weights (sum 1)
    int k, ox, oy, m;                               // product window and level
    int refineLevels;                               // lobe refinement levels below the leaves
    Frame frame;
    vec3 wo; // shading-local
    uint brdfType;
    vec3 baseColor;
    float roughness;
    vec2 cosSinYaw;
};

struct SamplerGlobals {
    uint kind;       // kSampler*
    bool lit;        // the env has light (else env techniques are absent)
    uint tailOffset; // word offset of the 8 x 8 env averages
    int envLevel;    // the env map's level N (2^N x 2^N texels)
    float envMean;   // the env map's mean luminance (its level-0 average)
    vec2 cosSinYaw;
};

vec3 envToLocal(vec2 cs, vec3 d) { return vec3(cs.x * d.x - cs.y * d.z, d.y, cs.y * d.x + cs.x * d.z); }
vec3 envToWorld(vec2 cs, vec3 d) { return vec3(cs.x * d.x + cs.y * d.z, d.y, -cs.y * d.x + cs.x * d.z); }

float luminanceOf(vec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

int pyramidOffset(int l) { return ((1 << (2 * l)) - 1) / 3; }

float dsBrdfCos(DirSampler s, vec3 wiWorld) {
    vec3 l = frameToLocal(s.frame, wiWorld);
    if (l.z <= 0.0) return 0.0;
    return luminanceOf(brdfEval(s.brdfType, s.baseColor, s.roughness, s.wo, l) * l.z);
}

// --- the product -------------------------------------------------------------------------

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

// The env's share of its total luminance in cell (l, x, y), by its quadtree's splits (uniform
// below the tree's leaves); `node` is the cell's node when `exact`, else a leaf above the cell.
double envCellMass(int l, int x, int y, out int node, out bool exact) {
    node = 0;
    int reached = 0;
    double mass = 1.0LF;
    while (reached < l && envNodes[node].firstChild >= 0) {
        int shift = l - reached - 1;
        int cx = (x >> shift) & 1, cy = (y >> shift) & 1;
        EnvNode n = envNodes[node];
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

// The probabilities of a node's four children (in (x, y) order: 0 = (0,0), 1 = (1,0),
// 2 = (0,1), 3 = (1,1)); false, and 1/4 each, for a leaf of the tree.
bool envChildShares(int node, out double w[4]) {
    w[0] = 0.25LF;
    w[1] = 0.25LF;
    w[2] = 0.25LF;
    w[3] = 0.25LF;
    if (envNodes[node].firstChild < 0) return false;
    EnvNode n = envNodes[node];
    double py0, py1, pl0, pr0, pl1, pr1;
    decodeSplit(n.py0, py0, py1);
    decodeSplit(n.px0y0, pl0, pr0);
    decodeSplit(n.px0y1, pl1, pr1);
    w[0] = py0 * pl0;
    w[1] = py0 * pr0;
    w[2] = py1 * pl1;
    w[3] = py1 * pr1;
    return true;
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

// BRDF x cos at the centres of the four sub-cells of global cell (l, x, y), weighted by the env's
// luminance there: sum_s L_s f(c_s) / sum_s L_s (the plain mean where the env is black). Times
// the env's average over the cell this is the mean of L f over the sub-cells, so a sun in the
// steep flank of a lobe gets the BRDF where it sits, not at the cell's centre (the CPU's
// windowTabulateEnvWeighted).
// `sub`: the env's shares in the sub-cells (envSubCellMasses).
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

// Decodes the env factor of `factor` (truncated Haar, SparseHaar's tree) to scaling
// coefficients at level m (haar.h's synthesis), multiplies each cell's average by the
// env-weighted BRDF x cos over its sub-cells, and sums the masses up. Returns the total mass (0:
// nothing to sample).
float dsBuildProduct(DirSampler s, SamplerMaterial sm, uint factor) {
    uint table = sm.tableOffset + 5u + 4u * samplerWords[sm.tableOffset + 3u] + 2u * factor;
    uint firstNode = samplerWords[table], nodeCount = samplerWords[table + 1u];
    int m = s.m;
    gMass[0] = uintBitsToFloat(samplerWords[sm.scalingOffset + factor]);
    gNode[0] = nodeCount > 0u ? 0 : -1;
    for (int l = 0; l < m; ++l) {
        int side = 1 << l, off = pyramidOffset(l), offChild = pyramidOffset(l + 1);
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                float sc = gMass[off + y * side + x];
                int node = gNode[off + y * side + x];
                vec3 d = vec3(0.0);
                uint base = 0u;
                if (node >= 0) {
                    base = sm.nodeOffset + (firstNode + uint(node)) * 10u;
                    d = vec3(uintBitsToFloat(samplerWords[base + 3u]),
                             uintBitsToFloat(samplerWords[base + 4u]),
                             uintBitsToFloat(samplerWords[base + 5u]));
                }
                float child[4] = float[4](0.5 * (sc + d.x + d.y + d.z), 0.5 * (sc - d.x + d.y - d.z),
                                          0.5 * (sc + d.x - d.y - d.z), 0.5 * (sc - d.x - d.y + d.z));
                for (int c = 0; c < 4; ++c) {
                    int i = offChild + (2 * y + (c >> 1)) * (2 * side) + 2 * x + (c & 1);
                    gMass[i] = child[c];
                    if (l + 1 < m) gNode[i] = node >= 0 ? int(samplerWords[base + 6u + uint(c)]) : -1;
                }
            }
    }
    // Leaves: average env luminance (2^m x the scaling coefficient), clamped at 0 (truncation
    // leaves negatives), times BRDF x cos env-weighted over the leaf's four sub-cells.
    int side = 1 << m, off = pyramidOffset(m);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            float e = max(0.0, gMass[off + y * side + x] * float(side));
            int gx = (s.ox << (m - 1)) + x, gy = (s.oy << (m - 1)) + y;
            double sub[4];
            if (e > 0.0) envSubCellMasses(s.k + m, gx, gy, sub);
            gMass[off + y * side + x] = e > 0.0 ? e * dsEnvWeightedBrdfCos(s, s.k + m, gx, gy, sub) : 0.0;
        }
    return dsSumPyramid(m);
}

// --- the oracle's dense product ---------------------------------------------------------------

// The smallest window (k <= maxK) holding the octahedral image of the cap of half-angle
// `halfAngle` around `axis` (env-local): render::chooseWindow's twin, probing 48 rim points on the
// cap's edge and at half its angle; an image wider than half the square gets the whole square.
void dsChooseWindow(vec3 axis, float halfAngle, int maxK, out int k, out int ox, out int oy) {
    k = 0;
    ox = 0;
    oy = 0;
    if (halfAngle >= 1.2 || maxK < 1) return;
    vec3 a = normalize(axis);
    vec3 helper = abs(a.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 t = normalize(cross(helper, a));
    vec3 b = cross(a, t);
    vec2 lo = octToSquare(a), hi = lo;
    for (int ring = 0; ring < 2; ++ring) {
        float theta = (ring == 0 ? 1.0 : 0.5) * halfAngle;
        for (int i = 0; i < 48; ++i) {
            float phi = 2.0 * kPi * float(i) / 48.0;
            vec3 d = cos(theta) * a + sin(theta) * (cos(phi) * t + sin(phi) * b);
            vec2 p = octToSquare(d);
            lo = min(lo, p);
            hi = max(hi, p);
        }
    }
    if (hi.x - lo.x > 0.5 || hi.y - lo.y > 0.5) return;
    for (int kk = maxK; kk >= 1; --kk) {
        double side = 1.0LF / double(1 << kk), halfSide = 0.5LF * side;
        int maxOrigin = (1 << (kk + 1)) - 2;
        int x0 = clamp(int(floor(double(lo.x) / halfSide)), 0, maxOrigin);
        int y0 = clamp(int(floor(double(lo.y) / halfSide)), 0, maxOrigin);
        if (double(x0) * halfSide + side >= double(hi.x) && double(y0) * halfSide + side >= double(hi.y)) {
            k = kk;
            ox = x0;
            oy = y0;
            return;
        }
    }
}

// The oracle's leaves: the leaf's exact env average times its env-weighted BRDF x cos, i.e. the
// mean over its 2 x 2 sub-cells of (env average there) x BRDF x cos at the sub-cell's centre: the
// masses of the dense product one level finer (the CPU's windowTabulateEnvWeighted x
// windowEnvGrid). Returns the total (0: nothing to sample).
float dsBuildOracleProduct(DirSampler s, float envMean) {
    int m = s.m, side = 1 << m, off = pyramidOffset(m);
    int level = s.k + m;
    double toAverage = powerOfFour(level) * double(envMean);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            int gx = (s.ox << (m - 1)) + x, gy = (s.oy << (m - 1)) + y;
            double sub[4];
            envSubCellMasses(level, gx, gy, sub);
            double mass = sub[0] + sub[1] + sub[2] + sub[3];
            gMass[off + y * side + x] =
                mass > 0.0LF ? float(mass * toAverage) * dsEnvWeightedBrdfCos(s, level, gx, gy, sub) : 0.0;
        }
    return dsSumPyramid(m);
}

// Each of two parts' own share of their sum (1/2 each when both are empty).
void dsParts(double a, double b, out double p0, out double p1) {
    double whole = a + b;
    p0 = whole > 0.0LF ? a / whole : 0.5LF;
    p1 = whole > 0.0LF ? b / whole : 0.5LF;
}

// Probabilities of the rows below cell (l, x, y) and of the columns given each row: in double
// from the float masses, each half its own share (1 - p would lose a sun's 1e-6).
void dsChildProbabilities(int l, int x, int y, out double pRow[2], out double pColumn[4]) {
    int side = 1 << (l + 1), off = pyramidOffset(l + 1);
    int c0 = off + 2 * y * side + 2 * x, c1 = c0 + side;
    double a = gMass[c0], b = gMass[c0 + 1], c = gMass[c1], d = gMass[c1 + 1];
    dsParts(a + b, c + d, pRow[0], pRow[1]);
    dsParts(a, b, pColumn[0], pColumn[1]);
    dsParts(c, d, pColumn[2], pColumn[3]);
}

// Lobe refinement below the product's leaves (EnvProductSampler's, CPU): for a few levels the four
// children of a cell are weighted by the env's own split of the cell (its quadtree's conditional
// probabilities: ratios of the children's averages) times BRDF x cos at the child's centre, plus
// 2% of the largest so no child with env light loses support. The weights depend only on the cell,
// so walking them again for a point gives the exact pdf.
const float kLobeFloor = 0.02;

void dsRefineWeights(DirSampler s, int l, int x, int y, out double w[4]) {
    int reached;
    int node = envFindNode(l, x, y, reached);
    w = double[4](0.25LF, 0.25LF, 0.25LF, 0.25LF);
    if (reached == l) envChildShares(node, w);
    double side = 1.0LF / double(1 << (l + 1));
    float h[4];
    float hmax = 0.0;
    for (int c = 0; c < 4; ++c) {
        dvec2 centre = (dvec2(2 * x + (c & 1), 2 * y + (c >> 1)) + 0.5LF) * side;
        h[c] = dsBrdfCos(s, envToWorld(s.cosSinYaw, octToDirection(vec2(centre))));
        hmax = max(hmax, h[c]);
    }
    if (hmax > 0.0 && !isinf(hmax))
        for (int c = 0; c < 4; ++c) w[c] *= double(h[c] + kLobeFloor * hmax);
}


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

// A point of the octahedral square from the product (leaf by the product's quadtree, then the
// env's quadtree inside it); `density` per unit square area.
dvec2 dsSampleProduct(DirSampler s, dvec2 u, out double density) {
    int x = 0, y = 0;
    double probability = 1.0LF;
    for (int l = 0; l < s.m; ++l) {
        double pRow[2], pColumn[4];
        dsChildProbabilities(l, x, y, pRow, pColumn);
        int cy = chooseShare(pRow[0], pRow[1], u.y, probability);
        int cx = chooseShare(pColumn[2 * cy], pColumn[2 * cy + 1], u.x, probability);
        x = 2 * x + cx;
        y = 2 * y + cy;
    }
    int shift = s.m - 1;
    int l = s.k + s.m;
    x += s.ox << shift;
    y += s.oy << shift;
    for (int r = 0; r < s.refineLevels; ++r) {
        double w[4], p0, p1;
        dsRefineWeights(s, l, x, y, w);
        dsParts(w[0] + w[1], w[2] + w[3], p0, p1);
        int cy = chooseShare(p0, p1, u.y, probability);
        dsParts(w[2 * cy], w[2 * cy + 1], p0, p1);
        int cx = chooseShare(p0, p1, u.x, probability);
        l += 1;
        x = 2 * x + cx;
        y = 2 * y + cy;
    }
    double q;
    dvec2 p = envSampleWithin(l, x, y, u, q);
    density = probability * q;
    return p;
}

// The product technique's density at square point p (0 outside its window).
double dsProductPdf(DirSampler s, dvec2 p) {
    int level = s.k + s.m, shift = s.m - 1;
    double scale = double(1 << level);
    int gx = int(p.x * scale), gy = int(p.y * scale);
    int lx = gx - (s.ox << shift), ly = gy - (s.oy << shift);
    int side = 1 << s.m;
    if (lx < 0 || ly < 0 || lx >= side || ly >= side) return 0.0LF;
    double probability = 1.0LF;
    int x = 0, y = 0;
    for (int l = 0; l < s.m; ++l) {
        double pRow[2], pColumn[4];
        dsChildProbabilities(l, x, y, pRow, pColumn);
        int cx = (lx >> (s.m - 1 - l)) & 1, cy = (ly >> (s.m - 1 - l)) & 1;
        probability *= pRow[cy] * pColumn[2 * cy + cx];
        x = 2 * x + cx;
        y = 2 * y + cy;
    }
    if (!(probability > 0.0LF)) return 0.0LF;
    for (int r = 0; r < s.refineLevels; ++r) {
        double w[4], p0, p1;
        dsRefineWeights(s, level, gx, gy, w);
        double childScale = double(1 << (level + 1));
        int cx = clamp(int(p.x * childScale) - 2 * gx, 0, 1);
        int cy = clamp(int(p.y * childScale) - 2 * gy, 0, 1);
        dsParts(w[0] + w[1], w[2] + w[3], p0, p1);
        probability *= cy == 0 ? p0 : p1;
        dsParts(w[2 * cy], w[2 * cy + 1], p0, p1);
        probability *= cx == 0 ? p0 : p1;
        level += 1;
        gx = 2 * gx + cx;
        gy = 2 * gy + cy;
    }
    if (!(probability > 0.0LF)) return 0.0LF;
    return probability * envPdfWithin(level, gx, gy, p);
}

// --- the mixture shares (DirectionSampler::addProduct) ----------------------------------------

// Second moment of env sampling over the 8^2 coarse cells outside the lobe's domain (the window
// when there is a product, else the cap widened by a cell).
double dsTailMoment(DirSampler s, SamplerGlobals g, bool product, vec3 axisLocal, float capAngle) {
    const int side = 1 << kTailLevel;
    float cellAngle = sqrt(kFourPi) / float(side);
    float cosCap = cos(min(capAngle + cellAngle, kPi));
    double windowScale = double(1 << s.k);
    dvec2 origin = dvec2(s.ox, s.oy) * (0.5LF / windowScale);
    double sum = 0.0LF;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            vec2 p = (vec2(x, y) + 0.5) / float(side);
            if (product) {
                dvec2 local = (dvec2(p) - origin) * windowScale;
                if (local.x >= 0.0LF && local.x < 1.0LF && local.y >= 0.0LF && local.y < 1.0LF) continue;
            }
            vec3 d = octToDirection(p);
            if (!product && dot(d, axisLocal) > cosCap) continue;
            float fcos = dsBrdfCos(s, envToWorld(s.cosSinYaw, d));
            double average = uintBitsToFloat(samplerWords[g.tailOffset + uint(y * side + x)]);
            sum += average * double(fcos) * double(fcos);
        }
    double dw = double(kFourPi) / double(side * side);
    return sum * double(g.envMean) * double(kFourPi) * dw;
}

// Stratified 4 x 4 BSDF draws with the env's texel averages: the mean of (g / p)^2.
double dsBsdfLobeMoment(DirSampler s, SamplerGlobals g) {
    double sum = 0.0LF;
    for (int j = 0; j < kLobeStrata; ++j)
        for (int i = 0; i < kLobeStrata; ++i) {
            vec3 wi, f;
            float pdf;
            if (!brdfSample(s.brdfType, s.baseColor, s.roughness, s.wo, (float(i) + 0.5) / kLobeStrata,
                            (float(j) + 0.5) / kLobeStrata, wi, f, pdf) ||
                !(pdf > 0.0))
                continue;
            dvec2 p = dvec2(octToSquare(envToLocal(s.cosSinYaw, frameToWorld(s.frame, wi))));
            double texel = envPdfWithin(0, 0, 0, p) * double(g.envMean);
            double v = double(luminanceOf(f)) * double(wi.z) / double(pdf) * texel;
            sum += v * v;
        }
    return sum / double(kLobeStrata * kLobeStrata);
}

// --- set-up, sampling, pdf ------------------------------------------------------------------

DirSampler dsSetup(SamplerGlobals g, SamplerMaterial sm, Frame frame, vec3 wo, uint brdfType,
                   vec3 baseColor, float roughness) {
    DirSampler s;
    s.cProduct = 0.0;
    s.cBsdf = 0.0;
    s.cEnv = 0.0;
    s.cUniform = 0.0;
    s.cCosine = 0.0;
    s.k = 0;
    s.ox = 0;
    s.oy = 0;
    s.m = 0;
    s.refineLevels = 0;
    s.frame = frame;
    s.wo = wo;
    s.brdfType = brdfType;
    s.baseColor = baseColor;
    s.roughness = roughness;
    s.cosSinYaw = g.cosSinYaw;
    if (g.kind == kSamplerUniform) {
        s.cUniform = 1.0;
        return s;
    }
    if (g.kind == kSamplerCosine) {
        s.cCosine = 1.0;
        return s;
    }
    if (!g.lit || g.kind == kSamplerBsdf) {
        s.cBsdf = 1.0;
        return s;
    }
    if (g.kind == kSamplerEnv) {
        s.cEnv = 1.0;
        return s;
    }
    if (g.kind == kSamplerMis) {
        s.cBsdf = 0.5;
        s.cEnv = 0.5;
        return s;
    }
    // wavelet, oracle
    if (sm.mode == kModeBsdfOnly) {
        s.cBsdf = 1.0;
        return s;
    }
    vec3 nWorld = frame.n, woWorld = frameToWorld(frame, wo);
    vec3 axisWorld = sm.aroundNormal != 0u ? nWorld : 2.0 * dot(woWorld, nWorld) * nWorld - woWorld;
    vec3 axisLocal = normalize(envToLocal(g.cosSinYaw, axisWorld));
    bool product = false;
    double lobeMoment = 0.0LF;
    float total = 0.0;
    if (sm.mode == kModeProduct) {
        uint header = sm.tableOffset;
        int b = int(samplerWords[header + 1u]);
        int bins = 1 << b;
        vec2 p = octToSquare(axisLocal);
        int bx = min(int(p.x * float(bins)), bins - 1), by = min(int(p.y * float(bins)), bins - 1);
        uint binWords = header + 5u + 4u * uint(by * bins + bx);
        s.k = int(samplerWords[binWords]);
        s.ox = int(samplerWords[binWords + 1u]);
        s.oy = int(samplerWords[binWords + 2u]);
        s.m = min(int(samplerWords[header + 2u]), kMaxProductLevel);
        s.refineLevels = dsRefineLevels(sm, s.k + s.m, g.envLevel);
        total = dsBuildProduct(s, sm, samplerWords[binWords + 3u]);
    } else if (sm.mode == kModeOracle) {
        int maxK = max(1, g.envLevel + kOracleDepthBelowEnv - kOracleLevel);
        dsChooseWindow(axisLocal, sm.capHalfAngle, maxK, s.k, s.ox, s.oy);
        s.m = kOracleLevel;
        s.refineLevels = dsRefineLevels(sm, s.k + s.m, g.envLevel);
        total = dsBuildOracleProduct(s, g.envMean);
    }
    if (sm.mode == kModeProduct || sm.mode == kModeOracle) {
        product = total > 0.0;
        if (product) {
            // The product's integral over the window's solid angle: its second moment is close
            // to that integral squared (the product is close to the lobe's integrand).
            double windowArea = 1.0LF / double(1 << (2 * s.k));
            double lobe = double(total) / double(1 << (2 * s.m)) * double(kFourPi) * windowArea;
            lobeMoment = lobe * lobe;
        }
    }
    if (!product) lobeMoment = dsBsdfLobeMoment(s, g);
    double tail = dsTailMoment(s, g, product, axisLocal, sm.capHalfAngle);
    double a = sqrt(max(tail, 0.0LF)), bm = sqrt(max(lobeMoment, 0.0LF));
    double minEnvShare = sm.mode == kModeOracle ? kOracleMinEnvShare : kMinEnvShare;
    double envShare = clamp(a / max(a + bm, 1e-300LF), minEnvShare, kMaxEnvShare);
    if (product) {
        s.cProduct = float(1.0LF - envShare - double(sm.mixBsdf));
        s.cBsdf = sm.mixBsdf;
        s.cEnv = float(envShare);
    } else {
        s.cBsdf = float(1.0LF - envShare);
        s.cEnv = float(envShare);
    }
    return s;
}

// The mixture's solid-angle pdf at world direction wi whose octahedral point (env-local) is p.
float dsMixturePdf(DirSampler s, vec3 wi, dvec2 p) {
    vec3 local = frameToLocal(s.frame, wi);
    double pdf = 0.0LF;
    if (s.cUniform > 0.0) pdf += double(s.cUniform) * (local.z > 0.0 ? double(0.5 * kInvPi) : 0.0LF);
    if (s.cCosine > 0.0) pdf += double(s.cCosine) * double(cosineHemispherePdf(local));
    if (s.cBsdf > 0.0) pdf += double(s.cBsdf) * double(brdfPdf(s.brdfType, s.roughness, s.wo, local));
    if (s.cEnv > 0.0) pdf += double(s.cEnv) * envPdfWithin(0, 0, 0, p) / double(kFourPi);
    if (s.cProduct > 0.0) pdf += double(s.cProduct) * dsProductPdf(s, p) / double(kFourPi);
    return float(pdf);
}

float dsPdf(DirSampler s, vec3 wi) {
    return dsMixturePdf(s, wi, dvec2(octToSquare(envToLocal(s.cosSinYaw, wi))));
}

// u3 picks the technique (in the CPU's order: product, bsdf, env), u1 and u2 drive it.
bool dsSample(DirSampler s, float u1, float u2, float u3, out vec3 wi, out float pdf) {
    wi = vec3(0.0);
    pdf = 0.0;
    if (s.cUniform > 0.0) {
        float z = u1, r = sqrt(max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * u2;
        wi = normalize(frameToWorld(s.frame, vec3(r * cos(phi), r * sin(phi), z)));
        pdf = dsPdf(s, wi);
        return pdf > 0.0;
    }
    if (s.cCosine > 0.0) {
        wi = normalize(frameToWorld(s.frame, sampleCosineHemisphere(vec2(u1, u2))));
        pdf = dsPdf(s, wi);
        return pdf > 0.0;
    }
    bool tabulated = false;
    dvec2 p = dvec2(0.0LF);
    double density;
    if (s.cProduct > 0.0 && u3 < s.cProduct) {
        p = dsSampleProduct(s, dvec2(u1, u2), density);
        tabulated = true;
    } else if (s.cEnv > 0.0 && (s.cBsdf == 0.0 || u3 >= s.cProduct + s.cBsdf)) {
        p = envSampleWithin(0, 0, 0, dvec2(u1, u2), density);
        tabulated = true;
    }
    if (tabulated) {
        wi = envToWorld(s.cosSinYaw, octToDirection(vec2(p)));
        pdf = dsMixturePdf(s, wi, p);
    } else {
        vec3 local, f;
        float bsdfPdf;
        if (!brdfSample(s.brdfType, s.baseColor, s.roughness, s.wo, u1, u2, local, f, bsdfPdf))
            return false;
        wi = normalize(frameToWorld(s.frame, local));
        pdf = dsPdf(s, wi);
    }
    return pdf > 0.0 && !isinf(pdf) && !isnan(wi.x);
}

#endif
