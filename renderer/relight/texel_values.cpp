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

// util::Frame::toLocal, inline (the same sums in the same order).
inline glm::vec3 toLocal(const util::Frame& f, const glm::vec3& w) {
    return glm::vec3(f.t.x * w.x + f.t.y * w.y + f.t.z * w.z, f.b.x * w.x + f.b.y * w.y + f.b.z * w.z,
                     f.n.x * w.x + f.n.y * w.y + f.n.z * w.z);
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

} // namespace

void visibleTexelValues(const TransferContext& ctx, const PreviewPoint& p, const PointState& s, bool withBlack,
                        TexelValues& out) {
    thread_local DirectionBatch dirs;
    thread_local Channels f, f0;
    const ResolvedMaterial& m = materialOf(ctx, p);
    const util::Frame frame = util::Frame::fromNormal(p.shading);
    const glm::vec3 wo = frame.toLocal(p.wo);
    const glm::vec3 mirror(-wo.x, -wo.y, wo.z);
    constexpr int kCount = TexelDirections::kSub * TexelDirections::kSub;
    const size_t gridTexels = ctx.dirs->count();
    dirs.reserve(gridTexels, gridTexels * (m.narrow ? kCount : 1));
    out.texel.resize(gridTexels);
    size_t texels = 0;
    forEachVisibleTexel(s, [&](size_t t) {
        out.texel[texels] = uint32_t(t);
        dirs.first[texels++] = uint32_t(dirs.size);
        const glm::vec3 local = toLocal(frame, ctx.dirs->direction(t));
        if (m.narrow && glm::dot(local, mirror) >= m.cosCap) {
            const glm::vec3* sub = ctx.dirs->subDirections(t);
            for (int k = 0; k < kCount; ++k) dirs.push(toLocal(frame, sub[k]));
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

} // namespace wavelit::relight
