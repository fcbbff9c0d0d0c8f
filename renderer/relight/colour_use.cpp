#include "relight/colour_use.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace wavelit::relight {
namespace {

glm::vec3 fromAngles(float cosTheta, float phi) {
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// wo at a few elevations; wi on a small grid of the hemisphere plus the mirror direction and
// two directions just off it (where a narrow lobe lives).
std::vector<std::pair<glm::vec3, glm::vec3>> probePairs() {
    std::vector<std::pair<glm::vec3, glm::vec3>> pairs;
    for (float cosO : {0.15f, 0.5f, 0.85f, 0.99f}) {
        const glm::vec3 wo = fromAngles(cosO, 0.3f);
        for (float cosI : {0.1f, 0.4f, 0.7f, 0.95f})
            for (float phi : {0.0f, 1.6f, 3.1f, 4.4f}) pairs.push_back({wo, fromAngles(cosI, phi)});
        const glm::vec3 mirror(-wo.x, -wo.y, wo.z);
        pairs.push_back({wo, mirror});
        pairs.push_back({wo, glm::normalize(mirror + glm::vec3(0.02f, 0.0f, 0.0f))});
        pairs.push_back({wo, glm::normalize(mirror + glm::vec3(0.0f, 0.05f, 0.0f))});
    }
    return pairs;
}

bool close(const glm::vec3& a, const glm::vec3& b, float scale) {
    for (int c = 0; c < 3; ++c)
        if (!(std::abs(a[c] - b[c]) <= 1e-5f * scale + 1e-12f)) return false; // NaN fails
    return true;
}

} // namespace

const char* colourUseName(ColourUse use) {
    switch (use) {
    case ColourUse::Fixed: return "fixed";
    case ColourUse::Ignored: return "ignored";
    case ColourUse::Linear: return "linear";
    case ColourUse::Affine: return "affine";
    }
    return "fixed";
}

ColourUse colourUseOf(const plugins::Brdf& brdf, const plugins::BrdfParams& params) {
    static const auto pairs = probePairs();
    const std::array<glm::vec3, 2> mixes = {glm::vec3(0.25f, 0.5f, 0.9f), glm::vec3(0.7f, 0.05f, 0.4f)};
    plugins::BrdfParams black = params, white = params, mixed = params;
    black.baseColor = glm::vec3(0.0f);
    white.baseColor = glm::vec3(1.0f);
    bool ignored = true, linear = true;
    for (const auto& [wo, wi] : pairs) {
        const glm::vec3 f0 = brdf.eval(black, wo, wi), f1 = brdf.eval(white, wo, wi);
        const float scale = std::max({std::abs(f0.x), std::abs(f0.y), std::abs(f0.z), std::abs(f1.x),
                                      std::abs(f1.y), std::abs(f1.z)});
        for (const glm::vec3& c : mixes) {
            mixed.baseColor = c;
            if (!close(brdf.eval(mixed, wo, wi), f0 + c * (f1 - f0), scale)) return ColourUse::Fixed;
        }
        ignored = ignored && f0 == f1;
        linear = linear && f0 == glm::vec3(0.0f);
    }
    if (ignored) return ColourUse::Ignored;
    return linear ? ColourUse::Linear : ColourUse::Affine;
}

bool greyAffine(const plugins::Brdf& brdf, const plugins::BrdfParams& params) {
    static const auto pairs = probePairs();
    plugins::BrdfParams black = params, white = params, red = params;
    black.baseColor = glm::vec3(0.0f);
    white.baseColor = glm::vec3(1.0f);
    red.baseColor = glm::vec3(1.0f, 0.0f, 0.0f);
    for (const auto& [wo, wi] : pairs) {
        const glm::vec3 f0 = brdf.eval(black, wo, wi), f1 = brdf.eval(white, wo, wi);
        const float scale = std::max({std::abs(f0.x), std::abs(f0.y), std::abs(f0.z), std::abs(f1.x),
                                      std::abs(f1.y), std::abs(f1.z)});
        if (!close(f0, glm::vec3(f0.x), scale) || !close(f1, glm::vec3(f1.x), scale)) return false;
        if (!close(brdf.eval(red, wo, wi), glm::vec3(f1.x, f0.x, f0.x), scale)) return false;
    }
    return true;
}

} // namespace wavelit::relight
