// An analytic light's radiance as seen from one preview point, projected onto the texels of the
// sphere grid: per texel, the integral of the light's radiance over the texel's solid angle
// (W m^-2 per channel), so <T, L_k> = sum over entries of T(texel) * weight. Seen from the point,
// not as a distant light: a rect 1 m away covers many texels, a far one a single texel.
//
// Units follow docs/estimator.md "Analytic lights" (the path tracer's): Point/Spot intensity
// I = P / 4 pi (Spot times its smoothstep falloff), one texel of weight I / D^2; Sphere radiance
// P / (4 pi^2 r^2) over its visible cone; Rect radiance P / (pi A) from its front face; Sun
// radiance E / (pi sin^2 theta_s) over its cone (E in one texel when its diameter is 0). A light
// that covers less than a quarter of a texel is one entry at its centre direction with its exact
// total; a larger one is integrated with s x s stratified samples, s from its solid angle in
// texels (about one per texel for a sphere or sun cone, one per two texels for a rect; at most
// 6 x 6), each sample's weight landing in the texel its direction falls in.
#pragma once

#include "relight/texel_directions.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace wavelit::relight {

struct TexelWeight {
    uint32_t texel = 0;
    glm::vec3 weight{0.0f}; // integral of radiance over the texel's solid angle
    // The power-weighted mean of the light's sample points in the texel: its distance (inf: the
    // sun) and direction (unit) from p. A shadow ray toward a local light aims there (for a rect
    // it lies on the light, so the ray stops at the light even where the texel's centre
    // direction passes beside it). And whether the whole light is smaller than a quarter texel
    // (one entry): then a narrow glossy lobe sees it at that direction rather than as the
    // texel's average (point_transfer.h).
    float distance = 0.0f;
    glm::vec3 direction{0.0f, 0.0f, 1.0f};
    bool compact = false;
};

// The light with colour 1 and intensity 1: a light's terms are computed per unit power and
// multiplied by lightPower() when the image is summed (radiance is linear in it), so an intensity
// or colour edit costs no per-point work.
scene::Light unitPowerLight(const scene::Light& light);
glm::vec3 lightPower(const scene::Light& light); // colour x intensity

// Sorted by texel, one entry per texel, no zero weights. p is the visibility rays' origin.
std::vector<TexelWeight> projectLight(const scene::Light& light, const glm::vec3& p,
                                      const TexelDirections& dirs);
// The same into `out` (cleared first), which keeps its capacity between calls.
void projectLight(const scene::Light& light, const glm::vec3& p, const TexelDirections& dirs,
                  std::vector<TexelWeight>& out);
// projectLight(unitPowerLight(light), ...) without copying the light (its name) per point: the
// same values bit for bit. `power` in place of colour x intensity.
void projectUnitLight(const scene::Light& light, const glm::vec3& p, const TexelDirections& dirs,
                      std::vector<TexelWeight>& out);
void projectLightWithPower(const scene::Light& light, const glm::vec3& power, const glm::vec3& p,
                           const TexelDirections& dirs, std::vector<TexelWeight>& out);

} // namespace wavelit::relight
