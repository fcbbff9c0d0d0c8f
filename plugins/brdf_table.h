// An isotropic measured BRDF in the MERL binary layout (Matusik et al. 2003, "A Data-Driven
// Reflectance Model"): three int32 counts (θh, θd, φd bins: 90, 90, 180 in the MERL files), then
// 3 × θh × θd × φd little-endian doubles, the red block, then green, then blue, each index
// φd + Nφd (θd + Nθd θh). A stored value v means f = v × scale: 1/1500, 1.15/1500, 1.66/1500 for
// R, G, B (the MERL reader's constants). The bins are MERL's:
//   θh bin = sqrt(θh / (π/2)) Nθh  (finer near the specular peak), θd bin = θd / (π/2) Nθd,
//   φd bin = φd / π Nφd with φd folded into [0, π) (reciprocity),
// and a bin's value is taken at its centre; eval interpolates multilinearly between centres
// (MERL's reader takes the nearest bin; interpolation keeps a coarse table's albedo).
// Counts other than 90 × 90 × 180 are accepted, so a small example can ship
// (resources/brdfs/; tools/make_measured_brdf.cpp writes one from an analytic plugin).
// The table is immutable once loaded and shared by every thread.
#pragma once

#include "plugins/brdf.h"
#include "util/result.h"

#include <glm/vec3.hpp>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace wavelit::plugins {

inline constexpr std::array<double, 3> kMerlScale{1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

struct BrdfTable {
    int thetaHalfBins = 90, thetaDiffBins = 90, phiDiffBins = 180;
    std::vector<float> f; // RGB per bin, already multiplied by kMerlScale: 3 * binCount() floats
    std::string file;     // where it was loaded from (for messages)
    // The cone about the normal holding half of f cosθi at normal view (radians; loadMerlBrdf
    // fills it): the lobe half-width `measured` declares to the samplers (plugins/brdf.h).
    double halfWidthAtNormalView = 0.5 * 3.14159265358979323846;

    size_t binCount() const { return size_t(thetaHalfBins) * thetaDiffBins * phiDiffBins; }
    // The bin MERL's reader would look up (nearest).
    size_t binOf(const glm::vec3& wo, const glm::vec3& wi) const;
    // f(wo, wi) in the local frame (z = normal), 0 below the horizon.
    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const;
};

// The angle θ about the normal within which half of ∫ luminance(f(n, wi)) cosθi dwi lies, for a
// view along the normal n (where the mirror direction is n too); π/2 for a table that is 0 there.
double tableHalfWidthAtNormalView(const BrdfTable& table);

// Errors name the file: unreadable, counts that are not positive or too large, a size that does
// not match the counts ("expected 34,992,012 bytes for 90 x 90 x 180 bins, found 4,096"), and the
// first non-finite or negative value with its bin.
util::Result<std::shared_ptr<const BrdfTable>> loadMerlBrdf(const std::string& path);

// The bytes of a MERL file that tabulates `brdf` (at the centre of each bin, in bin-index space)
// at the given counts: how the shipped example was made (tools/make_measured_brdf.cpp).
std::vector<char> tabulateMerlBrdf(const Brdf& brdf, const BrdfParams& params, int thetaHalfBins,
                                   int thetaDiffBins, int phiDiffBins);

} // namespace wavelit::plugins
