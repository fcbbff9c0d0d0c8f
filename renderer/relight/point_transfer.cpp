#include "relight/point_transfer.h"

#include "relight/light_projection.h"
#include "relight/texel_values.h"
#include "relight/transfer_compression.h"
#include "util/hemisphere_sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

namespace wavelit::relight {
namespace {

constexpr float kRayOffset = 1e-4f; // docs/estimator.md's scale-aware epsilon

// f at the material's primary parameters, and at black when `black` is given: one evaluation
// for a grey-affine BRDF (ResolvedMaterial::oneEval), else one per parameter set.
glm::vec3 evalPair(const ResolvedMaterial& m, const plugins::BrdfParams& params, const plugins::BrdfParams* black,
                   const glm::vec3& wo, const glm::vec3& wi, glm::vec3& f0) {
    if (black && m.oneEval && black == &m.black && &params == &m.params) {
        const glm::vec3 f = m.brdf->eval(m.red, wo, wi);
        f0 = glm::vec3(f.y);
        return glm::vec3(f.x);
    }
    if (black) f0 = m.brdf->eval(*black, wo, wi);
    return m.brdf->eval(params, wo, wi);
}

// cosine x f at a texel above the horizon, without visibility, with the given parameters, and
// with `black` too when given (one local direction and one lobe test for both).
glm::vec3 unshadowed(const TransferContext& ctx, const PreviewPoint& p, const util::Frame& frame,
                     const glm::vec3& wo, size_t texel, const plugins::BrdfParams& params,
                     const plugins::BrdfParams* black = nullptr, glm::vec3* blackOut = nullptr) {
    const glm::vec3& wi = ctx.dirs->direction(texel);
    const ResolvedMaterial& m = materialOf(ctx, p);
    const glm::vec3 local = frame.toLocal(wi);
    if (m.narrow && glm::dot(local, glm::vec3(-wo.x, -wo.y, wo.z)) >= m.cosCap) {
        constexpr int kCount = TexelDirections::kSub * TexelDirections::kSub;
        const float *sx = ctx.dirs->subX(texel), *sy = ctx.dirs->subY(texel), *sz = ctx.dirs->subZ(texel);
        glm::vec3 sum(0.0f), sum0(0.0f);
        for (int k = 0; k < kCount; ++k) {
            const glm::vec3 l = frame.toLocal(glm::vec3(sx[k], sy[k], sz[k]));
            if (l.z > 0.0f) {
                glm::vec3 f0(0.0f);
                sum += evalPair(m, params, black, wo, l, f0) * l.z;
                sum0 += f0 * l.z;
            }
        }
        if (black) *blackOut = sum0 / float(kCount);
        return sum / float(kCount);
    }
    glm::vec3 f0(0.0f);
    const glm::vec3 f = evalPair(m, params, black, wo, local, f0);
    if (black) *blackOut = f0 * local.z;
    return f * local.z;
}

bool visible(const PointState& s, size_t texel) { return testBit(s.lit, texel) && !blockedByOthers(s, texel); }

// visit(entry, white, black) for every entry of the light that the point sees, in projection
// order, with its contribution to <T, L_k> (black only when `black`): lightTermWith's sum term by
// term, and the shadow field's per-entry cache (drag_cache.h).
// `texelValue(texel, blackOut)`: f x cosine at a visible texel (unshadowed's value; the
// material's first answer has them from its batch already); nullptr: unshadowed at every texel.
template <class TexelValue, class Visit>
void forEachSeenLightEntry(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                           const scene::Light& light, bool black, TexelValue&& texelValue, Visit&& visit) {
    const ResolvedMaterial& m = materialOf(ctx, p);
    const util::Frame frame = util::Frame::fromNormal(p.shading);
    const glm::vec3 wo = frame.toLocal(p.wo);
    const glm::vec3 origin = rayOrigin(p);
    thread_local std::vector<TexelWeight> entries;
    projectUnitLight(light, origin, *ctx.dirs, entries);
    for (const TexelWeight& e : entries) {
        if (!testBit(s.above, e.texel)) continue;
        bool seen = visible(s, e.texel);
        if (!seen && std::isfinite(e.distance))
            seen = !scene::occluded(*ctx.sceneBvh, origin, e.direction, 0.0f, e.distance * (1.0f - 1e-3f));
        if (!seen) continue;
        // A narrow lobe near its mirror direction sees a light smaller than a texel where the
        // light is, not as the texel's average: a sun a tenth of a texel wide reflected in chrome
        // is one sharp highlight (the average would spread it over the texel's solid angle). A
        // light that fills texels keeps the texel average, which covers what it fills.
        const glm::vec3 local = e.compact && m.narrow ? frame.toLocal(e.direction) : glm::vec3(0.0f);
        if (e.compact && m.narrow && glm::dot(local, glm::vec3(-wo.x, -wo.y, wo.z)) >= m.cosCap) {
            if (local.z > 0.0f) {
                glm::vec3 f0(0.0f);
                const glm::vec3 w = evalPair(m, m.params, black ? &m.black : nullptr, wo, local, f0) * local.z * e.weight;
                visit(e, w, f0 * local.z * e.weight);
            }
            continue;
        }
        glm::vec3 f0(0.0f);
        glm::vec3 value;
        if constexpr (!std::is_null_pointer_v<std::remove_cvref_t<TexelValue>>) {
            if (visible(s, e.texel)) value = texelValue(e.texel, &f0);
            else value = unshadowed(ctx, p, frame, wo, e.texel, m.params, black ? &m.black : nullptr, &f0);
        } else {
            value = unshadowed(ctx, p, frame, wo, e.texel, m.params, black ? &m.black : nullptr, &f0);
        }
        const glm::vec3 w = value * e.weight;
        visit(e, w, black ? f0 * e.weight : glm::vec3(0.0f));
    }
}

// <T, L_k> for the primary parameters, and for black when `black` is given.
glm::vec3 lightTermWith(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                        const scene::Light& light, glm::vec3* black) {
    glm::vec3 sum(0.0f), sum0(0.0f);
    forEachSeenLightEntry(ctx, p, s, light, black != nullptr, nullptr,
                          [&](const TexelWeight&, const glm::vec3& w, const glm::vec3& b) {
                              sum += w;
                              sum0 += b;
                          });
    if (black) *black = sum0;
    return sum;
}

} // namespace

ResolvedMaterial resolveMaterial(const scene::Material& m, double texelRadius) {
    ResolvedMaterial r;
    r.brdf = plugins::findBrdf(m.brdf);
    if (!r.brdf) r.brdf = plugins::findBrdf(plugins::defaultBrdfName());
    r.params.baseColor = m.baseColor;
    r.params.roughness = m.roughness;
    r.params.anisotropy = m.anisotropy;
    r.params.table = m.brdfTable;
    r.baseColor = m.baseColor;
    r.emission = m.emission;
    r.colourUse = colourUseOf(*r.brdf, r.params);
    if (r.colourUse == ColourUse::Linear || r.colourUse == ColourUse::Affine) r.params.baseColor = glm::vec3(1.0f);
    r.black = r.params;
    r.black.baseColor = glm::vec3(0.0f);
    r.red = r.params;
    r.red.baseColor = glm::vec3(1.0f, 0.0f, 0.0f);
    r.oneEval = r.colourUse == ColourUse::Affine && greyAffine(*r.brdf, r.params);
    const plugins::BrdfLobeWidth lobe = r.brdf->lobeWidth(r.params);
    if (r.brdf->lobeAxis() == plugins::BrdfLobeAxis::Mirror && lobe.halfWidth < 2.0 * texelRadius) {
        r.narrow = true;
        const double cap = lobe.capHalfAngle + 2.0 * texelRadius;
        r.cosCap = cap >= 3.14159265358979 ? -2.0f : float(std::cos(cap));
        r.capAngle = std::acos(std::clamp(double(r.cosCap), -1.0, 1.0)); // of the float cosine kept
    }
    return r;
}

size_t PointState::bytes() const {
    size_t b = sizeof(PointState) + (above.capacity() + lit.capacity()) * sizeof(uint64_t) +
               transfer.index.capacity() * sizeof(uint16_t) +
               transfer.value.capacity() * sizeof(glm::vec3) + lightTerms.capacity() * sizeof(glm::vec3) +
               occlusions.capacity() * sizeof(Occlusion) + transfer0.index.capacity() * sizeof(uint16_t) +
               transfer0.value.capacity() * sizeof(glm::vec3) + lightTerms0.capacity() * sizeof(glm::vec3);
    for (const Occlusion& o : occlusions) b += o.blocked.capacity() * sizeof(uint64_t);
    return b;
}

glm::vec3 rayOrigin(const PreviewPoint& p) {
    return p.position + p.geometric * (kRayOffset * std::max(1.0f, glm::length(p.position)));
}

glm::vec3 transferAt(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                     size_t texel) {
    const util::Frame frame = util::Frame::fromNormal(p.shading);
    if (!visible(s, texel)) return glm::vec3(0.0f);
    return unshadowed(ctx, p, frame, frame.toLocal(p.wo), texel, materialOf(ctx, p).params);
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

// rebuildTransfer for a grey-affine material: f(white) and f(black) are grey (one evaluation
// gives both), so both T's are one channel each.
static void rebuildGreyTransfer(const TransferContext& ctx, PointState& s,
                                const TexelValues& values) {
    thread_local std::vector<double> texels, texels0;
    const int level = ctx.dirs->level();
    const size_t count = ctx.dirs->count();
    texels.assign(count, 0.0);
    texels0.assign(count, 0.0);
    const double finest = std::ldexp(1.0, -level);
    for (size_t j = 0; j < values.texel.size(); ++j) {
        texels[values.texel[j]] = double(values.white[j].x) * finest;
        texels0[values.texel[j]] = double(values.black[j].x) * finest;
    }
    compressGrey(texels, level, ctx.keep, s.transfer);
    compressGrey(texels0, level, ctx.keep, s.transfer0);
}

void rebuildTransfer(const TransferContext& ctx, const PreviewPoint& p, PointState& s) {
    thread_local std::vector<glm::dvec3> texels, texels0;
    thread_local TexelValues values;
    const ResolvedMaterial& m = materialOf(ctx, p);
    const bool affine = m.colourUse == ColourUse::Affine;
    const int level = ctx.dirs->level();
    const size_t count = ctx.dirs->count();
    visibleTexelValues(ctx, p, s, affine, values);
    if (affine && m.oneEval) {
        rebuildGreyTransfer(ctx, s, values);
        return;
    }
    texels.assign(count, glm::dvec3(0.0));
    if (affine) texels0.assign(count, glm::dvec3(0.0));
    // Finest scaling coefficients: 2^-n times the texel value (haar.h).
    const double finest = std::ldexp(1.0, -level);
    for (size_t j = 0; j < values.texel.size(); ++j) {
        texels[values.texel[j]] = glm::dvec3(values.white[j]) * finest;
        if (affine) texels0[values.texel[j]] = glm::dvec3(values.black[j]) * finest;
    }
    compressMaybeGrey(texels, level, ctx.keep, s.transfer);
    if (affine) compressMaybeGrey(texels0, level, ctx.keep, s.transfer0);
    else s.transfer0 = SparseTransfer{};
}

glm::vec3 environmentTerm(const SparseTransfer& t, const EnvironmentFactor& env) {
    glm::dvec3 sum(0.0);
    const glm::vec3* l = env.interleaved.data();
    for (size_t k = 0; k < t.index.size(); ++k) sum += glm::dvec3(t.value[k] * l[t.index[k]]);
    return glm::vec3(sum * (4.0 * std::numbers::pi));
}

glm::vec3 environmentTerm(const PointState& s, const EnvironmentFactor& env) {
    return environmentTerm(s.transfer, env);
}

glm::vec3 lightTerm(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                    const scene::Light& light) {
    return lightTermWith(ctx, p, s, light, nullptr);
}

void updateEnvironmentTerms(const TransferContext& ctx, PointState& s) {
    s.envTerm = environmentTerm(s.transfer, *ctx.environment);
    s.envTerm0 = s.transfer0.index.empty() ? glm::vec3(0.0f) : environmentTerm(s.transfer0, *ctx.environment);
}

void updateLightTerms(const TransferContext& ctx, const PreviewPoint& p, PointState& s, size_t k) {
    const auto& lights = ctx.scene->lighting.lights;
    s.lightTerms.resize(lights.size());
    if (materialOf(ctx, p).colourUse != ColourUse::Affine) {
        s.lightTerms0.clear();
        s.lightTerms[k] = lightTermWith(ctx, p, s, lights[k], nullptr);
        return;
    }
    s.lightTerms0.resize(lights.size());
    s.lightTerms[k] = lightTermWith(ctx, p, s, lights[k], &s.lightTerms0[k]);
}

void updateTransferAndTerms(const TransferContext& ctx, const PreviewPoint& p, PointState& s) {
    rebuildTransfer(ctx, p, s);
    updateEnvironmentTerms(ctx, s);
    s.lightTerms.clear();
    s.lightTerms0.clear();
    for (size_t k = 0; k < ctx.scene->lighting.lights.size(); ++k) updateLightTerms(ctx, p, s, k);
}

void untruncatedTerms(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                      const std::vector<glm::vec3>& envTexels, PointTerms& out,
                      LobeAverage average, float lobeCut) {
    thread_local TexelValues values;
    const ResolvedMaterial& m = materialOf(ctx, p);
    const bool affine = m.colourUse == ColourUse::Affine;
    float cosCut = -2.0f; // every visible texel
    if (lobeCut > 0.0f && m.narrow && m.cosCap > -1.0f)
        cosCut = float(std::cos(std::min(std::numbers::pi, double(lobeCut) * m.capAngle)));
    visibleTexelValues(ctx, p, s, affine, values, average, cosCut);
    glm::dvec3 env, env0;
    environmentSums(values, envTexels, env, env0);
    out.envTerm = glm::vec3(env);
    out.envTerm0 = glm::vec3(env0);
    // The light terms as lightTermWith sums them, taking f x cosine at visible texels from the
    // batch above (the same floats as unshadowed's: texel_values.h) instead of a scalar
    // evaluation per texel (a narrow lobe's: kSub^2 of them).
    thread_local std::vector<int32_t> slot;
    slot.resize(ctx.dirs->count(), -1);
    for (size_t j = 0; j < values.texel.size(); ++j) slot[values.texel[j]] = int32_t(j);
    auto texelValue = [&](size_t texel, glm::vec3* f0) {
        if (slot[texel] < 0) { // beyond the lobe's cut
            if (affine) *f0 = glm::vec3(0.0f);
            return glm::vec3(0.0f);
        }
        const size_t j = size_t(slot[texel]);
        if (affine) *f0 = values.black[j];
        return values.white[j];
    };
    const auto& lights = ctx.scene->lighting.lights;
    out.lightTerms.resize(lights.size());
    out.lightTerms0.resize(affine ? lights.size() : 0);
    for (size_t k = 0; k < lights.size(); ++k) {
        glm::vec3 sum(0.0f), sum0(0.0f);
        forEachSeenLightEntry(ctx, p, s, lights[k], affine, texelValue,
                              [&](const TexelWeight&, const glm::vec3& w, const glm::vec3& b) {
                                  sum += w;
                                  sum0 += b;
                              });
        out.lightTerms[k] = sum;
        if (affine) out.lightTerms0[k] = sum0;
    }
    for (const uint32_t t : values.texel) slot[t] = -1;
}

// The texels above both the geometric and the shading horizon.
static TexelBits aboveBits(const TexelDirections& dirs, const PreviewPoint& p) {
    return dirs.aboveBoth(p.geometric, p.shading);
}

PointState buildPointState(const TransferContext& ctx, const PreviewPoint& p, uint32_t skipObject,
                           const TexelBits* selfBlocked) {
    PointState s = visibilityState(ctx, p, skipObject, selfBlocked);
    updateTransferAndTerms(ctx, p, s);
    return s;
}

PointState visibilityState(const TransferContext& ctx, const PreviewPoint& p, uint32_t skipObject,
                           const TexelBits* selfBlocked) {
    PointState s;
    const TexelDirections& dirs = *ctx.dirs;
    TexelBits above = aboveBits(dirs, p);
    const glm::vec3 origin = rayOrigin(p);
    const ObjectOccluder& own = (*ctx.occluders)[p.object];
    const bool convex = p.backFace ? own.convexBack : own.convexFront;
    TexelBits self = convex ? makeBits(dirs.count()) : selfBlocked ? *selfBlocked : castOcclusion(own, origin, dirs, above);
    if (selfBlocked && !convex)
        for (size_t w = 0; w < self.size(); ++w) self[w] &= above[w];
    s.above = above;
    s.lit = above;
    for (size_t w = 0; w < s.lit.size(); ++w) s.lit[w] &= ~self[w];
    for (uint32_t j = 0; j < ctx.occluders->size(); ++j)
        if (j != skipObject) updateOcclusion(ctx, p, s, j);
    return s;
}

PointState carriedVisibilityState(const TransferContext& ctx, const PreviewPoint& p, const TexelBits* selfBlocked,
                                  const std::vector<Occlusion>& occlusions, const std::vector<glm::vec3>& envTexels,
                                  LobeAverage average, float lobeCut) {
    PointState s;
    s.above = aboveBits(*ctx.dirs, p);
    s.lit = s.above;
    if (selfBlocked)
        for (size_t w = 0; w < s.lit.size(); ++w) s.lit[w] &= ~(*selfBlocked)[w];
    for (const Occlusion& o : occlusions) {
        Occlusion within{o.object, o.blocked};
        bool any = false;
        for (size_t w = 0; w < within.blocked.size(); ++w) any |= (within.blocked[w] &= s.lit[w]) != 0;
        if (any) s.occlusions.push_back(std::move(within));
    }
    PointTerms terms;
    untruncatedTerms(ctx, p, s, envTexels, terms, average, lobeCut);
    s.envTerm = terms.envTerm;
    s.envTerm0 = terms.envTerm0;
    s.lightTerms = std::move(terms.lightTerms);
    s.lightTerms0 = std::move(terms.lightTerms0);
    return s;
}

void seenLightContributions(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                            const scene::Light& light, std::vector<LightContribution>& out) {
    out.clear();
    const bool affine = materialOf(ctx, p).colourUse == ColourUse::Affine;
    forEachSeenLightEntry(ctx, p, s, light, affine, nullptr,
                          [&](const TexelWeight& e, const glm::vec3& w, const glm::vec3& b) {
                              out.push_back(LightContribution{e.texel, e.distance, e.direction, w, b});
                          });
}

} // namespace wavelit::relight
