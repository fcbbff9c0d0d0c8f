// f x cosine at every visible texel of a preview point, for the BRDF's primary parameters and
// (an affine BRDF) black: the per-texel values T is made of (point_transfer.h), in one batched BRDF
// call per parameter set (plugins/brdf.h evalBatch) instead of one virtual eval per texel. The
// same floats as evaluating texel by texel (docs/relighting.md §7.0f); from-scratch builds,
// roughness edits and the shadow field's drag cache all take their T from here.
#pragma once

#include "relight/point_transfer.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace wavelit::relight {

inline const ResolvedMaterial& materialOf(const TransferContext& ctx, const PreviewPoint& p) {
    const auto& m = *ctx.materials;
    return m[std::min<size_t>(p.material, m.size() - 1)];
}

inline bool blockedByOthers(const PointState& s, size_t texel) {
    for (const Occlusion& o : s.occlusions)
        if (testBit(o.blocked, texel)) return true;
    return false;
}

// visit(t) for every visible texel t (lit, no other object in the way), walking the lit bits.
template <class Visit> void forEachVisibleTexel(const PointState& s, Visit&& visit) {
    for (size_t w = 0; w < s.lit.size(); ++w) {
        uint64_t visibleBits = s.lit[w]; // one word of every occlusion, not one test per texel
        for (const Occlusion& o : s.occlusions) visibleBits &= ~o.blocked[w];
        for (uint64_t bits = visibleBits; bits; bits &= bits - 1) visit(w * 64 + size_t(__builtin_ctzll(bits)));
    }
}

// The visible texels of a point, ascending, with f x cosine at each: `white` for the material's
// params, `black` for its black parameters when asked (affine BRDFs; else left empty). A
// grey-affine BRDF (ResolvedMaterial::oneEval) gives grey values from one evaluation. A narrow
// lobe's texels near the mirror direction average TexelDirections::kSub^2 sub-directions.
struct TexelValues {
    std::vector<uint32_t> texel;
    std::vector<glm::vec3> white, black;
};
// LobeAverage (point_transfer.h): how the narrow lobe's texels are averaged. cosCut: a narrow
// lobe's texels whose centre lies further than acos(cosCut) from the mirror direction are left
// out (untruncatedTerms' lobeCut; -2: none).
void visibleTexelValues(const TransferContext& ctx, const PreviewPoint& p, const PointState& s, bool withBlack,
                        TexelValues& out, LobeAverage average = LobeAverage::Full, float cosCut = -2.0f);

// The untruncated environment terms of values v (untruncatedTerms, and the drag cache's base for
// a surface the drag uncovers): the sum over v's texels in order of value x envTexels[texel]
// (L(t) x the texel solid angle), in double — white into env, black into env0 (0 when v has none).
void environmentSums(const TexelValues& v, const std::vector<glm::vec3>& envTexels, glm::dvec3& env,
                     glm::dvec3& env0);

} // namespace wavelit::relight
