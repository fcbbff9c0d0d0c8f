#include "relight/texel_values.h"

#include "util/hemisphere_sampling.h"

#include <glm/geometric.hpp>

namespace wavelit::relight {
namespace {

// The local directions of one point's batch, structure of arrays (what evalBatch reads), and
// where each texel's directions start: one (the centre) or kSub^2 (a narrow lobe's texel).
// Sized once per thread for the worst case and written by index (push_back's capacity checks
// were a sixth of a roughness edit).
struct DirectionBatch {
    std::vector<float> x, y, z;
    std::vector<uint32_t> first; // per texel, + the end
    size_t size = 0;
    void reserve(size_t texels, size_t directions) {
        if (x.size() < directions) {
            x.resize(directions);
            y.resize(directions);
            z.resize(directions);
        }
        if (first.size() < texels + 1) first.resize(texels + 1);
        size = 0;
    }
    void push(const glm::vec3& l) {
        x[size] = l.x;
        y[size] = l.y;
        z[size] = l.z;
        ++size;
    }
};

// Frame::toLocal of n directions given as arrays (a texel's sub-directions, or every texel
// centre of the grid): lane by lane the same products and sums as toLocal (no FMA without
// -march), written so the compiler vectorises them (restrict parameters; §7.0f: restrict on
// local pointers is ignored).
void directionsToLocal(const util::Frame& f, size_t n, const float* __restrict sx, const float* __restrict sy,
                       const float* __restrict sz, float* __restrict x, float* __restrict y, float* __restrict z) {
    for (size_t k = 0; k < n; ++k) {
        x[k] = f.t.x * sx[k] + f.t.y * sy[k] + f.t.z * sz[k];
        y[k] = f.b.x * sx[k] + f.b.y * sy[k] + f.b.z * sz[k];
        z[k] = f.n.x * sx[k] + f.n.y * sy[k] + f.n.z * sz[k];
    }
}

struct Channels {
    std::vector<float> r, g, b;
    plugins::BrdfValues values(size_t n) {
        r.resize(n);
        g.resize(n);
        b.resize(n);
        return {r.data(), g.data(), b.data()};
    }
    glm::vec3 at(size_t i) const { return glm::vec3(r[i], g[i], b[i]); }
};

// products[i] = f[i] x z[i] where z[i] > 0, else +0 (vectorised; the same products as f x cosine
// one by one).
void maskedCosineProducts(size_t n, const float* __restrict f, const float* __restrict z,
                          float* __restrict products) {
    for (size_t i = 0; i < n; ++i) products[i] = z[i] > 0.0f ? f[i] * z[i] : 0.0f;
}

// The grey-affine values (ResolvedMaterial::oneEval: f(white) in red, f(black) in green), the
// same floats as the general loop in visibleTexelValues: a centre's f x cosine, or a narrow
// texel's sum, in direction order, of f x cosine over its directions above the horizon (+0 for the
// others, which leaves the non-negative sum as it is) over Count — one channel of each. The
// products first (vectorised), then the narrow texels' sums four texels at a time: each sum is
// still one chain of additions in order, but four independent chains overlap (one chain alone
// waited on each addition: a sixth of this function).
template <int Count>
void greyValues(const uint32_t* first, size_t texels, const float* z, const Channels& f, TexelValues& out) {
    thread_local std::vector<float> white, black;
    thread_local std::vector<uint32_t> narrow;
    const size_t n = first[texels];
    white.resize(n);
    black.resize(n);
    maskedCosineProducts(n, f.r.data(), z, white.data());
    maskedCosineProducts(n, f.g.data(), z, black.data());
    narrow.clear();
    for (size_t j = 0; j < texels; ++j) {
        const size_t begin = first[j];
        if (first[j + 1] - begin != 1) {
            narrow.push_back(uint32_t(j));
            continue;
        }
        out.white[j] = glm::vec3(f.r[begin] * z[begin]);
        out.black[j] = glm::vec3(f.g[begin] * z[begin]);
    }
    constexpr float kInv = 1.0f / float(Count); // a power of two: the same as dividing
    size_t g = 0;
    for (; g + 4 <= narrow.size(); g += 4) {
        const float* w[4];
        const float* b[4];
        for (int l = 0; l < 4; ++l) {
            w[l] = &white[first[narrow[g + size_t(l)]]];
            b[l] = &black[first[narrow[g + size_t(l)]]];
        }
        float sw[4] = {0.0f, 0.0f, 0.0f, 0.0f}, sb[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        for (int k = 0; k < Count; ++k)
            for (int l = 0; l < 4; ++l) {
                sw[l] += w[l][k];
                sb[l] += b[l][k];
            }
        for (int l = 0; l < 4; ++l) {
            out.white[narrow[g + size_t(l)]] = glm::vec3(sw[l] * kInv);
            out.black[narrow[g + size_t(l)]] = glm::vec3(sb[l] * kInv);
        }
    }
    for (; g < narrow.size(); ++g) {
        const size_t begin = first[narrow[g]];
        float sw = 0.0f, sb = 0.0f;
        for (int k = 0; k < Count; ++k) {
            sw += white[begin + size_t(k)];
            sb += black[begin + size_t(k)];
        }
        out.white[narrow[g]] = glm::vec3(sw * kInv);
        out.black[narrow[g]] = glm::vec3(sb * kInv);
    }
}

// visibleTexelValues with a narrow lobe's texels averaged over Sub x Sub sub-directions.
template <int Sub>
void valuesAveragedOver(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                        bool withBlack, TexelValues& out, float cosCut) {
    constexpr bool kFull = Sub == TexelDirections::kSub;
    static_assert(kFull || Sub == TexelDirections::kCoarseSub);
    const TexelDirections& grid = *ctx.dirs;
    thread_local DirectionBatch dirs;
    thread_local Channels f, f0;
    const ResolvedMaterial& m = materialOf(ctx, p);
    const util::Frame frame = util::Frame::fromNormal(p.shading);
    const glm::vec3 wo = frame.toLocal(p.wo);
    const glm::vec3 mirror(-wo.x, -wo.y, wo.z);
    constexpr int kCount = Sub * Sub;
    const size_t gridTexels = ctx.dirs->count();
    dirs.reserve(gridTexels, gridTexels * (m.narrow ? kCount : 1));
    out.texel.resize(gridTexels);
    // Every texel's centre in the point's frame at once (vectorised; the same products and sums as
    // Frame::toLocal), read below at the visible ones, instead of one scalar transform per
    // visible texel (docs/relighting.md §7.0j).
    thread_local std::vector<float> localX, localY, localZ;
    localX.resize(grid.paddedCount());
    localY.resize(grid.paddedCount());
    localZ.resize(grid.paddedCount());
    directionsToLocal(frame, grid.paddedCount(), grid.xs(), grid.ys(), grid.zs(), localX.data(), localY.data(),
                   localZ.data());
    size_t texels = 0;
    forEachVisibleTexel(s, [&](size_t t) {
        const glm::vec3 local(localX[t], localY[t], localZ[t]);
        const float toMirror = m.narrow ? glm::dot(local, mirror) : 0.0f; // the cosine to it
        if (m.narrow && toMirror < cosCut) return;
        out.texel[texels] = uint32_t(t);
        dirs.first[texels++] = uint32_t(dirs.size);
        if (m.narrow && toMirror >= m.cosCap) {
            const size_t at = dirs.size;
            if constexpr (kFull)
                directionsToLocal(frame, kCount, grid.subX(t), grid.subY(t), grid.subZ(t), &dirs.x[at],
                                  &dirs.y[at], &dirs.z[at]);
            else
                directionsToLocal(frame, kCount, grid.coarseSubX(t), grid.coarseSubY(t), grid.coarseSubZ(t),
                                  &dirs.x[at], &dirs.y[at], &dirs.z[at]);
            dirs.size += kCount;
        } else {
            dirs.push(local);
        }
    });
    out.texel.resize(texels);
    const size_t n = dirs.size;
    dirs.first[texels] = uint32_t(n);
    const plugins::BrdfDirections wi{dirs.x.data(), dirs.y.data(), dirs.z.data(), n};
    const bool one = withBlack && m.oneEval; // f(red): white in red, black in green (evalPair)
    m.brdf->evalBatch(one ? m.red : m.params, wo, wi, f.values(n));
    const bool two = withBlack && !one;
    if (two) m.brdf->evalBatch(m.black, wo, wi, f0.values(n));
    // f and f(black) at direction i, as the per-texel evaluation gave them.
    auto white = [&](size_t i) { return one ? glm::vec3(f.r[i]) : f.at(i); };
    auto black = [&](size_t i) { return one ? glm::vec3(f.g[i]) : two ? f0.at(i) : glm::vec3(0.0f); };
    out.white.resize(texels);
    out.black.resize(withBlack ? texels : 0);
    if (one) {
        greyValues<kCount>(dirs.first.data(), texels, dirs.z.data(), f, out);
        return;
    }
    for (size_t j = 0; j < texels; ++j) {
        const size_t begin = dirs.first[j], end = dirs.first[j + 1];
        if (end - begin == 1) {
            const float cosine = dirs.z[begin];
            out.white[j] = white(begin) * cosine;
            if (withBlack) out.black[j] = black(begin) * cosine;
            continue;
        }
        // The narrow lobe's average over the texel: directions below the horizon add nothing.
        glm::vec3 sum(0.0f), sum0(0.0f);
        for (size_t i = begin; i < end; ++i) {
            const float cosine = dirs.z[i];
            if (cosine > 0.0f) {
                sum += white(i) * cosine;
                sum0 += black(i) * cosine;
            }
        }
        out.white[j] = sum / float(kCount);
        if (withBlack) out.black[j] = sum0 / float(kCount);
    }
}

} // namespace

void visibleTexelValues(const TransferContext& ctx, const PreviewPoint& p, const PointState& s, bool withBlack,
                        TexelValues& out, LobeAverage average, float cosCut) {
    if (average == LobeAverage::Coarse)
        valuesAveragedOver<TexelDirections::kCoarseSub>(ctx, p, s, withBlack, out, cosCut);
    else
        valuesAveragedOver<TexelDirections::kSub>(ctx, p, s, withBlack, out, cosCut);
}

void environmentSums(const TexelValues& v, const std::vector<glm::vec3>& envTexels, glm::dvec3& env,
                     glm::dvec3& env0) {
    env = env0 = glm::dvec3(0.0);
    const bool black = !v.black.empty();
    for (size_t j = 0; j < v.texel.size(); ++j) {
        const glm::dvec3 l(envTexels[v.texel[j]]);
        env += glm::dvec3(v.white[j]) * l;
        if (black) env0 += glm::dvec3(v.black[j]) * l;
    }
}

} // namespace wavelit::relight
