// The shadow field of one movable object (Zhou et al. 2005, "Precomputed shadow fields for
// dynamic scenes"): its occlusion mask O_j over the sphere grid, precomputed once at sample
// positions around it, so that a translation drag looks O_j up per preview point instead of
// ray-casting it (docs/relighting.md §7.0e).
//
// Samples lie on `shells` concentric spheres about the object's bounding-sphere centre, radii
// log-spaced from innerRatio to outerRatio times the bounding radius, each at the texel-centre
// directions of a 2^directionLevel octahedral grid (texel_directions.h). Each holds one bit per
// texel of the preview's grid (`maskDirs`): set where the ray from the sample along the texel's
// centre direction hits the object (castOcclusion on the object's own BVH, every texel of the
// bounding cone) — bit for bit what RelightPreview casts for a point at that position. A lookup
// takes the nearest sample (shell by log radius, direction by texel): the position sampling is
// the approximation. Offsets beyond the outer shell return null (the caller ray-casts: the
// object covers a few texels there). Only translations keep a field valid: it lives in world axes.
// Immutable after build; lookups are thread-safe.
#pragma once

#include "relight/object_occluder.h"
#include "relight/texel_directions.h"

#include <glm/vec3.hpp>

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace wavelit::relight {

struct ShadowFieldSettings {
    int shells = 32;
    int directionLevel = 5; // 2^l x 2^l sample directions per shell
    float innerRatio = 0.25f; // innermost shell radius / bounding radius
    float outerRatio = 24.0f; // outermost shell radius / bounding radius
    bool interpolate = true;  // blend() the 8 samples about a point; false: the nearest (lookup)
    // The drag's use of the field (relight_preview.h enableShadowField), not the field itself:
    // the points on the moved object take their visibility from the drag start's nearest point of
    // it (self and other objects' occlusion) and their terms untruncated with their own BRDF,
    // instead of rays and a new T.
    bool reuseOwnStates = false;
    // With reuseOwnStates, > 0: those points' narrow lobes summed only within carriedLobeCut x
    // the lobe's cap angle of the mirror direction (untruncatedTerms' lobeCut; the editor's 2:
    // docs/relighting.md §7.0k). 0: every visible texel.
    float carriedLobeCut = 0.0f;
    bool operator==(const ShadowFieldSettings&) const = default;
};

class ShadowField {
public:
    // The field of `occluder` where it is now (its bounds' centre is the field's origin).
    // `cancel`, when given and set meanwhile, ends the build early (an incomplete field: drop it).
    static ShadowField build(const ObjectOccluder& occluder, const TexelDirections& maskDirs,
                             const ShadowFieldSettings& settings, int threads,
                             const std::atomic<bool>* cancel = nullptr);

    // The mask (words() words, maskDirs' texels) at `offset` = point - the object's bounding
    // centre; null beyond the outer shell's reach.
    const uint64_t* lookup(const glm::vec3& offset) const;
    // The interpolated field (Zhou et al.'s trilinear blend): up to 8 samples — the two shells
    // about the offset's log radius x the 4 directions about it on the octahedral square
    // (bilinear, clamped at the square's edges) — and their weights (summing to 1). Exactly on
    // a sample, that sample alone with weight 1. False beyond the outer shell's reach.
    struct Blend {
        const uint64_t* masks[8];
        float weights[8];
        int count = 0;
    };
    bool blend(const glm::vec3& offset, Blend& out) const;
    // Sample (shell, direction)'s offset from the centre, and its mask.
    glm::vec3 sampleOffset(size_t shell, size_t direction) const;
    const uint64_t* sampleMask(size_t shell, size_t direction) const;

    size_t shells() const { return m_radii.size(); }
    size_t directions() const { return m_dirs ? m_dirs->count() : 0; }
    size_t words() const { return m_words; }
    size_t maskTexels() const { return m_maskTexels; } // the mask grid's texel count
    size_t bytes() const {
        return m_masks.size() * sizeof(uint64_t) + m_radii.size() * sizeof(float) + m_inside.size();
    }
    size_t insideSamples() const;
    const ShadowFieldSettings& settings() const { return m_settings; }

private:
    ShadowFieldSettings m_settings;
    std::shared_ptr<const TexelDirections> m_dirs; // sample directions
    std::vector<float> m_radii;
    float m_logInner = 0.0f, m_logStep = 1.0f, m_reach = 0.0f;
    size_t m_words = 0, m_maskTexels = 0;
    std::vector<uint64_t> m_masks; // (shell * directions + direction) * words
    // Per sample: inside the object (its rays hit it in >= 98% of the directions). Reported, not
    // used: leaving them out of blends made the ring's contact zone worse (relighting.md §7.0e).
    std::vector<uint8_t> m_inside;
};

} // namespace wavelit::relight
