// One preview point's factors and cached products (paper §4, eqs 21-26; architecture.md §5.A).
//
// Factors on the sphere grid, all in the global frame:
//   Õ1 = self-visibility x cosine: `lit` marks the texels above both the geometric and the shading
//        horizon that the point's own object does not block; the cosine is max(0, wi . n_s);
//   O_j = occlusion by object j: `occlusions` holds the blocked texels of each other object that
//        blocks at least one lit texel (none stored for the others: O_j = 1);
//   f   = the BRDF toward the camera, the material's plugin eval (plugins/brdf.h), RGB;
//   L, L_k = environment and lights (environment_factor.h, light_projection.h).
// T = Õ1 x prod O_j x f is the product of the factors a lighting edit does not touch. It is kept
// as its K largest Haar coefficients (RGB, ranked by luminance-weighted magnitude) for the
// environment term 4 pi <T, L>, and evaluated from the factors at a light's few texels for the
// light terms <T, L_k> (exact at the grid's resolution; a point light needs T at one texel, where
// K-term truncation error would be largest). The O factors are visibility at infinite distance
// (right for the environment); a local light is seen when nothing lies between it and the point,
// so a light texel that they mark blocked gets one shadow ray up to the light's distance (an
// unblocked one needs none: blocked within a distance implies blocked at infinity). In an open
// scene that is almost no rays; inside a box (the Cornell box's ceiling light) one per light
// texel. Lighting is linear, so the radiance is the sum of
// the environment term and one term per light, each rebuilt alone when its light changes.
#pragma once

#include "relight/colour_use.h"
#include "relight/environment_factor.h"
#include "relight/object_occluder.h"
#include "relight/preview_points.h"
#include "relight/texel_directions.h"
#include "plugins/brdf.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace wavelit::relight {

struct Occlusion {
    uint32_t object = 0;
    TexelBits blocked;
};

struct SparseTransfer {
    std::vector<uint16_t> index; // haar.h dense layout, ascending
    std::vector<glm::vec3> value;
};

struct PointState {
    TexelBits above; // texels above both the geometric and the shading horizon
    TexelBits lit;   // above, and not blocked by the point's own object
    std::vector<Occlusion> occlusions; // ascending object index
    // T, its environment term and light terms for the material's primary parameters
    // (ResolvedMaterial::params: white for a colour-linear or colour-affine BRDF).
    SparseTransfer transfer;
    glm::vec3 envTerm{0.0f};           // per unit environmentScale()
    std::vector<glm::vec3> lightTerms; // per Scene::lighting.lights entry, per unit lightPower()
    // The same for black (ResolvedMaterial::black), for a colour-affine BRDF only (else empty):
    // the image takes black + colour x (white - black) per channel.
    SparseTransfer transfer0;
    glm::vec3 envTerm0{0.0f};
    std::vector<glm::vec3> lightTerms0;
    size_t bytes() const;
};

struct ResolvedMaterial {
    const plugins::Brdf* brdf = nullptr;
    // The parameters T is computed with: the material's own, or white for Linear / Affine.
    plugins::BrdfParams params;
    plugins::BrdfParams black; // Affine: the same with baseColor 0
    // Affine with a grey a and b (greyAffine): f(white) and f(black) from one evaluation at
    // `red` (baseColor (1, 0, 0)): red channel white, green channel black.
    bool oneEval = false;
    plugins::BrdfParams red;
    ColourUse colourUse = ColourUse::Fixed;
    glm::vec3 baseColor{0.8f}; // the material's own colour (mixed in by the image)
    glm::vec3 emission{0.0f};
    // A glossy lobe narrower than a texel: f x cosine is averaged over each texel within
    // cosCap of the mirror direction (TexelDirections::kSub^2 directions) instead of taken at
    // the centre, which would alias a highlight in or out of the texel.
    bool narrow = false;
    float cosCap = 1.0f;
    double capAngle = 0.0; // acos(cosCap): the cap's half-angle (radians), for untruncatedTerms' lobe cut
};

// The material as the preview uses it; texelRadius from the sphere grid.
ResolvedMaterial resolveMaterial(const scene::Material& m, double texelRadius);

// What every point's computation reads; immutable while points are computed in parallel.
struct TransferContext {
    const scene::Scene* scene = nullptr;
    const TexelDirections* dirs = nullptr;
    const std::vector<ObjectOccluder>* occluders = nullptr; // per Scene::objects entry
    const scene::Bvh* sceneBvh = nullptr; // every object: shadow rays toward local lights
    const std::vector<ResolvedMaterial>* materials = nullptr; // per material, + the default last
    const EnvironmentFactor* environment = nullptr;
    size_t keep = 128; // K: Haar coefficients of T kept per point (>= 4^n keeps all)
};

// The ray origin for a point's visibility rays: off the surface along n_g, as the path tracer.
glm::vec3 rayOrigin(const PreviewPoint& p);

// Everything: self-visibility, every object's occlusion, T, the environment and light terms
// (every object but `skipObject`: the shadow field's drag leaves the dragged object out, then
// adds it from the field, drag_cache.h).
// `selfBlocked`, when given, stands for the self-visibility rays of a non-convex object (the
// texels its own object blocks, masked by the point's horizon): the shadow-field drag's own
// surface cache (relight_preview.h).
PointState buildPointState(const TransferContext& ctx, const PreviewPoint& p,
                           uint32_t skipObject = UINT32_MAX, const TexelBits* selfBlocked = nullptr);
// buildPointState's visibility alone: the horizon, self-visibility and the other objects'
// occlusions (every object but `skipObject`), no T and no terms — for a point whose terms come
// from elsewhere until it is rebuilt (the shadow-field drag's uncovered surface, drag_cache.h).
PointState visibilityState(const TransferContext& ctx, const PreviewPoint& p,
                           uint32_t skipObject = UINT32_MAX, const TexelBits* selfBlocked = nullptr);
// Re-casts object j's occlusion over the lit texels its bounding cone may cover and
// stores it when anything is blocked (never for the point's own object: that is Õ1).
void updateOcclusion(const TransferContext& ctx, const PreviewPoint& p, PointState& s, uint32_t j);
// Rebuilds T's coefficients from the factors (after f or an O_j changed).
void rebuildTransfer(const TransferContext& ctx, const PreviewPoint& p, PointState& s);
// T at one texel at full resolution (the factors' product there).
glm::vec3 transferAt(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                     size_t texel);
// 4 pi <T_K, L> from the kept coefficients (per unit intensity x tint).
glm::vec3 environmentTerm(const PointState& s, const EnvironmentFactor& env);
glm::vec3 environmentTerm(const SparseTransfer& t, const EnvironmentFactor& env);
// <T, L_k> over the light's texels, per unit colour x intensity.
glm::vec3 lightTerm(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                    const scene::Light& light);
// The cached terms, for the primary and (Affine) the black parameters alike: the environment
// terms, light k's terms, or T and every term.
void updateEnvironmentTerms(const TransferContext& ctx, PointState& s);
void updateLightTerms(const TransferContext& ctx, const PreviewPoint& p, PointState& s, size_t k);
void updateTransferAndTerms(const TransferContext& ctx, const PreviewPoint& p, PointState& s);
// The point's radiance from its cached terms (per unit power; the material's colour mixed in
// per ColourUse): environment term x envScale + sum of light terms x powers.
glm::vec3 mixTerms(const ResolvedMaterial& m, const PointState& s, const glm::vec3& envScale,
                   const std::vector<glm::vec3>& lightPowers);

// A point's terms as PointState caches them (white, and black for an Affine BRDF), on their own.
struct PointTerms {
    glm::vec3 envTerm{0.0f}, envTerm0{0.0f};
    std::vector<glm::vec3> lightTerms, lightTerms0;
};
glm::vec3 mixTerms(const ResolvedMaterial& m, const PointTerms& t, const glm::vec3& envScale,
                   const std::vector<glm::vec3>& lightPowers);
// The terms without T (a material edit's first answer, docs/relighting.md §7.0g): the environment
// term as the texel sum of f x cosine x visibility x L(t) dOmega over the visible texels — by
// Parseval 4 pi <T, L> with every Haar coefficient kept, so no transform and no top K — and each
// light term as lightTerm computes it (never from T). `envTexels`: L(t) dOmega per texel per unit
// environmentScale(), the inverse Haar transform of the environment factor (environment_factor.h
// envTexelValues).
// How a narrow lobe's texels near its mirror direction are averaged: Full, over
// TexelDirections::kSub^2 sub-directions (what T is built from); Coarse, over kCoarseSub^2 (a
// quarter of the BRDF evaluations: a material edit's approximate first answer, docs/relighting.md
// §7.0h).
enum class LobeAverage { Full, Coarse };

// Reads s's visibility only, so s may hold T of another material. `average`: how a narrow lobe's
// texels are averaged. lobeCut > 0: a narrow lobe is summed only over the texels within lobeCut x
// its cap's half-angle of the mirror direction (the cap holds >= 89% of the lobe by the plugins'
// contract; what lies beyond lobeCut caps is left out: an approximation, docs/relighting.md §7.0k).
void untruncatedTerms(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                      const std::vector<glm::vec3>& envTexels, PointTerms& out,
                      LobeAverage average, float lobeCut = 0.0f);

// A point's state without rays and without T (the shadow-field drag's moved object,
// relight_preview.h): its horizon from its own normals, its self-visibility `selfBlocked` (null:
// none, a convex object) and the other objects' `occlusions` carried from another point (both
// masked by the horizon), and its terms untruncatedTerms' with its own BRDF and view direction.
// T is left empty: such a state is an approximation to be rebuilt (buildPointState) before any
// edit that reads T.
PointState carriedVisibilityState(const TransferContext& ctx, const PreviewPoint& p, const TexelBits* selfBlocked,
                                  const std::vector<Occlusion>& occlusions, const std::vector<glm::vec3>& envTexels,
                                  LobeAverage average, float lobeCut = 0.0f);

// One entry of light k that a point sees, with its share of <T, L_k> (white, black for Affine).
struct LightContribution {
    uint32_t texel = 0;
    float distance = 0.0f;     // to the light's samples in the texel (inf: the sun)
    glm::vec3 direction{0.0f}; // toward them (unit)
    glm::vec3 white{0.0f}, black{0.0f};
};
// lightTerm's sum term by term, in its order: the term is the sum of `out`'s white (black).
void seenLightContributions(const TransferContext& ctx, const PreviewPoint& p, const PointState& s,
                            const scene::Light& light, std::vector<LightContribution>& out);

} // namespace wavelit::relight
