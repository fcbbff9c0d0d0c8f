#include "relight/point_transfer.h"

#include "relight/light_projection.h"
#include "util/hemisphere_sampling.h"
#include "wavelet/haar.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace wavelit::relight {
namespace {

constexpr float kRayOffset = 1e-4f; // docs/estimator.md's scale-aware epsilon

const ResolvedMaterial& materialOf(const TransferContext& ctx, const PreviewPoint& p) {
    const auto& m = *ctx.materials;
    return m[std::min<size_t>(p.material, m.size() - 1)];
}

bool blockedByOthers(const PointState& s, size_t texel) {
    for (const Occlusion& o : s.occlusions)
        if (testBit(o.blocked, texel)) return true;
    return false;
}

// cosine x f at a texel above the horizon, without visibility.
glm::vec3 unshadowed(const TransferContext& ctx, const PreviewPoint& p, const util::Frame& frame,
                     const glm::vec3& wo, size_t texel) {
    const glm::vec3& wi = ctx.dirs->direction(texel);
    const ResolvedMaterial& m = materialOf(ctx, p);
    const glm::vec3 local = frame.toLocal(wi);
    if (m.narrow && glm::dot(local, glm::vec3(-wo.x, -wo.y, wo.z)) >= m.cosCap) {
        constexpr int kCount = TexelDirections::kSub * TexelDirections::kSub;
        const glm::vec3* sub = ctx.dirs->subDirections(texel);
        glm::vec3 sum(0.0f);
        for (int k = 0; k < kCount; ++k) {
            const glm::vec3 l = frame.toLocal(sub[k]);
            if (l.z > 0.0f) sum += m.brdf->eval(m.params, wo, l) * l.z;
        }
        return sum / float(kCount);
    }
    return m.brdf->eval(m.params, wo, local) * local.z;
}

glm::vec3 transferWithFrame(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                            const util::Frame& frame, const glm::vec3& wo, size_t texel) {
    if (!testBit(s.lit, texel) || blockedByOthers(s, texel)) return glm::vec3(0.0f);
    return unshadowed(ctx, p, frame, wo, texel);
}

} // namespace

ResolvedMaterial resolveMaterial(const scene::Material& m, double texelRadius) {
    ResolvedMaterial r;
    r.brdf = plugins::findBrdf(m.brdf);
    if (!r.brdf) r.brdf = plugins::findBrdf(plugins::defaultBrdfName());
    r.params.baseColor = m.baseColor;
    r.params.roughness = m.roughness;
    r.emission = m.emission;
    const plugins::BrdfLobeWidth lobe = r.brdf->lobeWidth(r.params);
    if (r.brdf->lobeAxis() == plugins::BrdfLobeAxis::Mirror && lobe.halfWidth < 2.0 * texelRadius) {
        r.narrow = true;
        const double cap = lobe.capHalfAngle + 2.0 * texelRadius;
        r.cosCap = cap >= 3.14159265358979 ? -2.0f : float(std::cos(cap));
    }
    return r;
}

size_t PointState::bytes() const {
    size_t b = sizeof(PointState) + (above.capacity() + lit.capacity()) * sizeof(uint64_t) +
               transfer.index.capacity() * sizeof(uint16_t) +
               transfer.value.capacity() * sizeof(glm::vec3) + lightTerms.capacity() * sizeof(glm::vec3) +
               occlusions.capacity() * sizeof(Occlusion);
    for (const Occlusion& o : occlusions) b += o.blocked.capacity() * sizeof(uint64_t);
    return b;
}

glm::vec3 rayOrigin(const PreviewPoint& p) {
    return p.position + p.geometric * (kRayOffset * std::max(1.0f, glm::length(p.position)));
}

glm::vec3 transferAt(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                     size_t texel) {
    const util::Frame frame = util::Frame::fromNormal(p.shading);
    return transferWithFrame(ctx, p, s, frame, frame.toLocal(p.wo), texel);
}

void updateOcclusion(const TransferContext& ctx, const PreviewPoint& p, PointState& s, uint32_t j) {
    auto it = std::lower_bound(s.occlusions.begin(), s.occlusions.end(), j,
                               [](const Occlusion& o, uint32_t v) { return o.object < v; });
    if (it != s.occlusions.end() && it->object == j) it = s.occlusions.erase(it);
    if (j == p.object) return;
    const ObjectOccluder& occluder = (*ctx.occluders)[j];
    const glm::vec3 origin = rayOrigin(p);
    const TexelBits cone = coneTexels(occluder.bounds, origin, *ctx.dirs, s.lit);
    if (!anyBit(cone)) return;
    TexelBits blocked = castOcclusion(occluder, origin, *ctx.dirs, cone);
    if (anyBit(blocked)) s.occlusions.insert(it, Occlusion{j, std::move(blocked)});
}

void rebuildTransfer(const TransferContext& ctx, const PreviewPoint& p, PointState& s) {
    // Scratch buffers per worker thread: a material edit rebuilds T on thousands of points, and
    // allocating three grids and three pyramids for each cost as much as the transform.
    thread_local std::vector<glm::dvec3> texels, parent, coeffs;
    thread_local std::vector<std::pair<double, uint32_t>> ranked;
    const int level = ctx.dirs->level();
    const size_t count = ctx.dirs->count();
    texels.assign(count, glm::dvec3(0.0));
    const util::Frame frame = util::Frame::fromNormal(p.shading);
    const glm::vec3 wo = frame.toLocal(p.wo);
    // Finest scaling coefficients: 2^-n times the texel value (haar.h).
    const double finest = std::ldexp(1.0, -level);
    for (size_t w = 0; w < s.lit.size(); ++w)
        for (uint64_t bits = s.lit[w]; bits; bits &= bits - 1) {
            const size_t t = w * 64 + size_t(__builtin_ctzll(bits));
            texels[t] = glm::dvec3(transferWithFrame(ctx, p, s, frame, wo, t)) * finest;
        }
    // wavelet::forwardHaar's nonstandard decomposition, the three channels in one pass.
    coeffs.assign(count, glm::dvec3(0.0));
    for (int l = level - 1; l >= 0; --l) {
        const int side = 1 << l, childSide = side * 2;
        parent.assign(size_t(side) * size_t(side), glm::dvec3(0.0));
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const size_t r0 = size_t(2 * y) * size_t(childSide), r1 = r0 + size_t(childSide);
                const size_t base = wavelet::detailIndex(l, x, y, 0);
                for (int c = 0; c < 3; ++c) {
                    const double child[4] = {texels[r0 + size_t(2 * x)][c], texels[r0 + size_t(2 * x) + 1][c],
                                             texels[r1 + size_t(2 * x)][c], texels[r1 + size_t(2 * x) + 1][c]};
                    double d[3];
                    wavelet::haarAnalyze(child, parent[size_t(y) * size_t(side) + size_t(x)][c], d);
                    coeffs[base][c] = d[0];
                    coeffs[base + 1][c] = d[1];
                    coeffs[base + 2][c] = d[2];
                }
            }
        texels.swap(parent);
    }
    coeffs[0] = texels[0];
    ranked.clear();
    for (size_t i = 1; i < count; ++i) {
        const glm::dvec3& v = coeffs[i];
        const double score = 0.2126 * std::abs(v.x) + 0.7152 * std::abs(v.y) + 0.0722 * std::abs(v.z);
        if (score > 0.0) ranked.push_back({-score, uint32_t(i)}); // ascending = largest first
    }
    const size_t details = ctx.keep > 1 ? ctx.keep - 1 : 0;
    if (ranked.size() > details) {
        std::nth_element(ranked.begin(), ranked.begin() + std::ptrdiff_t(details), ranked.end());
        ranked.resize(details);
    }
    s.transfer.index.clear();
    s.transfer.index.push_back(0); // the scaling coefficient (the integral) is always kept
    for (const auto& r : ranked) s.transfer.index.push_back(uint16_t(r.second));
    std::sort(s.transfer.index.begin(), s.transfer.index.end());
    s.transfer.value.resize(s.transfer.index.size());
    for (size_t k = 0; k < s.transfer.index.size(); ++k)
        s.transfer.value[k] = glm::vec3(coeffs[s.transfer.index[k]]);
}

glm::vec3 environmentTerm(const PointState& s, const EnvironmentFactor& env) {
    glm::dvec3 sum(0.0);
    const glm::vec3* l = env.interleaved.data();
    for (size_t k = 0; k < s.transfer.index.size(); ++k)
        sum += glm::dvec3(s.transfer.value[k] * l[s.transfer.index[k]]);
    return glm::vec3(sum * (4.0 * std::numbers::pi));
}

glm::vec3 lightTerm(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                    const scene::Light& light) {
    const util::Frame frame = util::Frame::fromNormal(p.shading);
    const glm::vec3 wo = frame.toLocal(p.wo);
    const glm::vec3 origin = rayOrigin(p);
    glm::vec3 sum(0.0f);
    for (const TexelWeight& e : projectLight(unitPowerLight(light), origin, *ctx.dirs)) {
        if (!testBit(s.above, e.texel)) continue;
        bool seen = testBit(s.lit, e.texel) && !blockedByOthers(s, e.texel);
        if (!seen && std::isfinite(e.distance))
            seen = !scene::occluded(*ctx.sceneBvh, origin, ctx.dirs->direction(e.texel), 0.0f,
                                    e.distance * (1.0f - 1e-3f));
        if (seen) sum += unshadowed(ctx, p, frame, wo, e.texel) * e.weight;
    }
    return sum;
}

PointState buildPointState(const TransferContext& ctx, const PreviewPoint& p) {
    PointState s;
    const TexelDirections& dirs = *ctx.dirs;
    TexelBits above = makeBits(dirs.count());
    for (size_t t = 0; t < dirs.count(); ++t)
        if (glm::dot(dirs.direction(t), p.geometric) > 0.0f && glm::dot(dirs.direction(t), p.shading) > 0.0f)
            setBit(above, t);
    const glm::vec3 origin = rayOrigin(p);
    const TexelBits self = castOcclusion((*ctx.occluders)[p.object], origin, dirs, above);
    s.above = above;
    s.lit = above;
    for (size_t w = 0; w < s.lit.size(); ++w) s.lit[w] &= ~self[w];
    for (uint32_t j = 0; j < ctx.occluders->size(); ++j) updateOcclusion(ctx, p, s, j);
    rebuildTransfer(ctx, p, s);
    s.envTerm = environmentTerm(s, *ctx.environment);
    for (const scene::Light& light : ctx.scene->lighting.lights)
        s.lightTerms.push_back(lightTerm(ctx, p, s, light));
    return s;
}

} // namespace wavelit::relight
