// Per preview point, what a translation drag of one object j needs besides j's shadow field
// (shadow_field.h, docs/relighting.md §7.0e): the point's factors with O_j left out, so that its
// terms with j anywhere are a masked sum over the texels j blocks — no ray, no BRDF evaluation,
// no Haar transform per frame.
//   environment: 4 pi <T_K, L> = envBase - sum over t in (O_j & visible') of T'(t) L(t) dOmega,
//     where T' = T without O_j, visible' its visible texels and envBase = 4 pi <(T')_K, L>. With all
//     coefficients kept this is the exact term; with K kept it differs from the exact preview's
//     4 pi <(T' (1 - O_j))_K, L> by the two truncations' difference (the masked part is exact);
//   light k: the entries of <T', L_k> the point sees without j (seenLightContributions, shadow
//     rays on the scene without j), each dropped where j's mask blocks its texel and — for a local
//     light — j's bounding sphere starts before the light along the entry's direction (the exact
//     preview casts a shadow ray there; the sphere test is the approximation).
// The cache does not depend on where j is, so a drag's result depends on the cache and the new
// mask only (an incremental drag equals one step from the same cache).
#pragma once

#include "relight/object_occluder.h"
#include "relight/point_transfer.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace wavelit::relight {

struct PointDragCache {
    bool valid = false;
    TexelBits visible;         // lit, not blocked by any object but j
    std::vector<uint16_t> rank; // per word of `visible`: its set bits in the words before
    uint8_t channels = 1;       // floats per texel per parameter set: 1 (T' grey) or 3
    bool affine = false;        // a black set follows the white one
    std::vector<float> values;  // T'(t) per visible texel: white, then black (affine)
    glm::vec3 envBase{0.0f}, envBase0{0.0f};
    std::vector<std::vector<LightContribution>> lights; // per light
    // Per light: the texels its entries lie in, and the entries' sums in order (white, black):
    // the light's terms wherever the mask blocks none of those texels, without the entries' walk.
    std::vector<TexelBits> lightTexels;
    std::vector<glm::vec3> lightSum, lightSum0;
    size_t bytes() const;
};

// `without`: the point's state with O_j left out and T, T_0 and the environment terms built from
// it; `ctxWithout`: the preview's context with sceneBvh on every object but j.
// With `envTexels` (L(t) x the texel solid angle) `without` needs its visibility only
// (visibilityState): the environment base is then the untruncated texel sum of T' L (what every
// Haar coefficient of T' would give), not 4 pi <T'_K, L>, and no T is built.
PointDragCache buildDragCache(const TransferContext& ctxWithout, const PreviewPoint& p, const PointState& without,
                              const std::vector<glm::vec3>* envTexels = nullptr);

// The point's terms (envTerm(0), lightTerms(0)) with j's mask `mask` (null or all zero: j blocks
// nothing) and j's bounding sphere now. `envTexels`: L(t) x the texel solid angle, per texel.
// `objectBvh` (j's own BVH), when given, decides a local light's entries in j's mask with the
// exact preview's shadow ray (on j alone) instead of the bounding-sphere test.
// `weight` (per texel, read where `mask` is set; null: 1) is j's occlusion there, fractional for an
// interpolated field (ShadowField::blend): the blocked share of the texel's T' L and of its light
// entries is removed.
void applyDragMask(const PointDragCache& cache, const uint64_t* mask, const BoundingSphere& sphere,
                   const glm::vec3& origin, const std::vector<glm::vec3>& envTexels, PointState& s,
                   const scene::Bvh* objectBvh = nullptr, const float* weight = nullptr);

} // namespace wavelit::relight
