// The end of a sample drawn as a half vector h (blinn, ward): wi = reflect(−wo, h), its pdf and f
// from the plugin's own pdf() and eval(), so the sample agrees with them exactly. A facet seen from
// behind (wo·h <= 0) or a reflection below the horizon gives an invalid sample: the path ends.
#pragma once

#include "plugins/brdf.h"

#include <glm/geometric.hpp>

namespace wavelit::plugins {

inline BrdfSample reflectAboutHalfVector(const Brdf& brdf, const BrdfParams& p, const glm::vec3& wo,
                                         const glm::vec3& h) {
    BrdfSample s;
    const float woh = glm::dot(wo, h);
    if (woh <= 0.0f) return s;
    s.wi = glm::normalize(2.0f * woh * h - wo);
    if (s.wi.z <= 0.0f) return s;
    s.pdf = brdf.pdf(p, wo, s.wi);
    s.f = brdf.eval(p, wo, s.wi);
    s.valid = s.pdf > 0.0f;
    return s;
}

} // namespace wavelit::plugins
