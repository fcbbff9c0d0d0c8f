#include "util/hemisphere_sampling.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace wavelit::util {

glm::vec2 sampleConcentricDisk(glm::vec2 u) {
    glm::vec2 o = 2.0f * u - glm::vec2(1.0f);
    if (o.x == 0.0f && o.y == 0.0f) return glm::vec2(0.0f);
    float r, theta;
    if (std::abs(o.x) > std::abs(o.y)) {
        r = o.x;
        theta = (kPi / 4.0f) * (o.y / o.x);
    } else {
        r = o.y;
        theta = kPi / 2.0f - (kPi / 4.0f) * (o.x / o.y);
    }
    return r * glm::vec2(std::cos(theta), std::sin(theta));
}

// Inverse of the map above: the wedge is chosen by which of |x|, |y| dominates, exactly the
// cases of the forward map (r keeps the sign of o.x or o.y there).
glm::vec2 invertConcentricDisk(glm::vec2 p) {
    float r = std::sqrt(p.x * p.x + p.y * p.y);
    if (r == 0.0f) return glm::vec2(0.5f);
    float phi = std::atan2(p.y, p.x); // (-π, π]
    glm::vec2 o;
    if (std::abs(p.x) >= std::abs(p.y)) {
        // theta = π/4 · o.y/o.x with r = o.x: o.x has the sign of p.x.
        float rs = p.x >= 0.0f ? r : -r;
        float theta = p.x >= 0.0f ? phi : (phi > 0.0f ? phi - kPi : phi + kPi);
        o = glm::vec2(rs, rs * theta / (kPi / 4.0f));
    } else {
        float rs = p.y >= 0.0f ? r : -r;
        float theta = p.y >= 0.0f ? phi : phi + kPi; // p.y < 0 → phi in (-π, 0)
        o = glm::vec2(rs * (kPi / 2.0f - theta) / (kPi / 4.0f), rs);
    }
    return glm::clamp(0.5f * (o + glm::vec2(1.0f)), glm::vec2(0.0f), glm::vec2(1.0f));
}

glm::vec3 sampleCosineHemisphere(glm::vec2 u) {
    glm::vec2 d = sampleConcentricDisk(u);
    float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return glm::vec3(d.x, d.y, z);
}

float cosineHemispherePdf(const glm::vec3& w) { return w.z > 0.0f ? w.z * kInvPi : 0.0f; }

glm::vec2 invertCosineHemisphere(const glm::vec3& w) {
    return invertConcentricDisk(glm::vec2(w.x, w.y));
}

glm::vec3 sampleUniformHemisphere(glm::vec2 u) {
    float z = u.x;
    float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    float phi = 2.0f * kPi * u.y;
    return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

float uniformHemispherePdf(const glm::vec3& w) { return w.z > 0.0f ? 0.5f * kInvPi : 0.0f; }

glm::vec2 invertUniformHemisphere(const glm::vec3& w) {
    float phi = std::atan2(w.y, w.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    return glm::vec2(w.z, std::min(phi / (2.0f * kPi), 1.0f));
}

Frame Frame::fromNormal(const glm::vec3& n) {
    float sign = std::copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    Frame f;
    f.t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.b = glm::vec3(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

} // namespace wavelit::util
