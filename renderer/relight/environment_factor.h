// The environment factor L of the relighting product: shared by every preview point (it lives in
// the global frame), so an environment edit costs one resampling and one Haar transform per
// channel plus a K-term dot product per point. The equirect map is splatted onto the octahedral
// grid with the wavelet core's energy-preserving resampler (a sun keeps its energy at 32^2), in
// the rotated frame (architecture.md §3: rotation is a yaw about +Y). Intensity x tint is NOT in
// the factor: radiance is linear in it, so the preview multiplies each point's environment term
// by environmentScale() when it sums the image, and an intensity or tint edit costs no per-point
// work at all (and stays bit-identical to a build from scratch).
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <array>
#include <memory>
#include <vector>

namespace wavelit::relight {

struct EnvironmentFactor {
    int level = 0;
    std::array<std::vector<double>, 3> coefficients; // Haar, haar.h's dense layout, per channel
    // The same as RGB floats, one load per kept coefficient of T in the per-point dot product
    // (the sum itself runs in double).
    std::vector<glm::vec3> interleaved;
};

// The equirect map reduced for a 2^level grid: b x b blocks averaged with their texels' solid
// angles as weights (the integral over the sphere is kept exactly), b the largest power of two
// that leaves at least 8 source columns per grid texel across. A rotation edit resamples this
// (4x fewer texels for the bundled 512 x 256 maps at 32^2), not the file's map.
std::shared_ptr<const util::ImageRGB> reduceEquirect(const util::ImageRGB& image, int level);

// `reduced`: reduceEquirect(*env.image, level), or null when the environment has no image.
EnvironmentFactor buildEnvironmentFactor(const scene::Environment& env, int level,
                                         const util::ImageRGB* reduced);

// intensity x tint.
glm::vec3 environmentScale(const scene::Environment& env);

// The radiance per unit environmentScale() a camera ray that escapes along dir sees
// (docs/estimator.md "Environment": the nearest texel after the yaw rotation), for background
// pixels of the preview.
glm::vec3 environmentRadiance(const scene::Environment& env, const glm::vec3& dir);

class TexelDirections;
// L(t) dOmega per texel of `dirs` per unit environmentScale(): the inverse Haar transform of the
// factor, times the texel's solid angle (zero everywhere without an environment). What the
// material edit's first answer sums against (point_transfer.h untruncatedTerms).
std::vector<glm::vec3> envTexelValues(const EnvironmentFactor& env, const TexelDirections& dirs);

} // namespace wavelit::relight
