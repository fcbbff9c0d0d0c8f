// Powers of a cosine, the shape `phong` (about the mirror direction) and `blinn` (of the half
// vector) share, computed through x = 1 − cosθ so a lobe with exponent 1e7 (roughness 0.02) keeps
// its shape in float: cosθ itself rounds to 1 there, x does not when it comes from a chord
// (1 − w·a = |w − a|² / 2) or from sin²θ / (1 + cosθ). GLSL twin: cosine_power.glsl.
#pragma once

#include <algorithm>
#include <cmath>

namespace wavelit::plugins::cosine_power {

// The floor of alpha = r² every glossy plugin shares (as ggx.cpp): narrower is a mirror.
inline constexpr float kMinAlpha = 1e-4f;

inline float alphaOf(float roughness) { return std::max(roughness * roughness, kMinAlpha); }

// The Phong exponent whose lobe matches a Beckmann lobe of the same alpha (Walter et al. 2007,
// "Microfacet Models for Refraction", eq. 30): n = 2/α² − 2, so roughness means the same width
// for every glossy plugin (architecture.md §3). r = 1 gives n = 0.
inline float exponentOf(float roughness) {
    const float a = alphaOf(roughness);
    return 2.0f / (a * a) - 2.0f;
}

// log(1 − x) for x in [0, 1), accurate for tiny x (GLSL has no log1p).
inline float logOneMinus(float x) {
    if (x < 1e-2f) return -x * (1.0f + x * (0.5f + x * (1.0f / 3.0f + x * 0.25f)));
    return std::log(1.0f - x);
}

// (1 − x)^n: cos^n θ given x = 1 − cosθ; 0 for x >= 1 (at or past 90 degrees).
inline float powOneMinus(float x, float n) {
    if (x >= 1.0f) return n == 0.0f && x == 1.0f ? 1.0f : 0.0f;
    return std::exp(n * logOneMinus(x));
}

// Draws x = 1 − cosθ with density ∝ cos^(m−1)θ on the hemisphere (cosθ = (1 − u)^(1/m));
// 1 − u keeps the log finite for u in [0, 1).
inline float sampleOneMinusCos(float u, float m) {
    const float t = -std::log(1.0f - u) / m; // −log cosθ
    return t < 1e-3f ? t * (1.0f - t * (0.5f - t * (1.0f / 6.0f))) : 1.0f - std::exp(-t);
}

// The u that sampleOneMinusCos maps to x.
inline float invertOneMinusCos(float x, float m) {
    return std::clamp(1.0f - powOneMinus(x, m), 0.0f, 1.0f);
}

} // namespace wavelit::plugins::cosine_power
