#include "render/lights/light_sampler.h"

#include "util/hemisphere_sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace wavelit::render {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Below this squared distance (m²) a point light's I/D² would overflow float once multiplied by a
// sharp BRDF; such a light sits on the shading point and its contribution is dropped.
constexpr float kMinDistance2 = 1e-12f;
// Rect axes: switch the reference from +Y to +Z when the normal is this close to ±Y.
constexpr float kVerticalNormal = 0.999f;
// pdf() and evalHit() accept cones (sun, sphere) this much wider in sin θ than sample() draws,
// so a sampled direction rounded across the rim (a unit vector's float components carry ~1e-7
// absolute error; a 0.53° sun has sin θs = 4.6e-3) still lies in the support its pdf admits.
// It widens the emitting cone by 2e-4 of its solid angle.
constexpr float kRimSlack2 = (1.0f + 1e-4f) * (1.0f + 1e-4f);
// The same for a rect light's edges, in units of its half extents (float rounding of a point
// sampled on an edge and intersected again).
constexpr float kEdgeSlack = 1.0f + 1e-5f;

// Uniform direction in the cone around `axis` whose half angle has 1 − cos θmax = oneMinusCos:
// x = 1 − cos θ = u1 · oneMinusCos (uniform in cos θ = uniform in solid angle), φ = 2π u2.
// sin²θ = x (2 − x) avoids the cancellation of 1 − cos²θ for tiny cones.
glm::vec3 sampleCone(const glm::vec3& axis, float oneMinusCos, float u1, float u2, float& sin2) {
    const float x = u1 * oneMinusCos;
    sin2 = std::max(0.0f, x * (2.0f - x));
    const float sinTheta = std::sqrt(sin2);
    const float phi = 2.0f * util::kPi * u2;
    const util::Frame frame = util::Frame::fromNormal(axis);
    return glm::normalize(frame.toWorld(
        glm::vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), 1.0f - x)));
}

float conePdf(float oneMinusCos) { return 1.0f / (2.0f * util::kPi * oneMinusCos); }

// 1 − cos θmax of a sphere of squared radius r2 seen from squared distance d2 > r2, via
// sin²θmax / (1 + cos θmax) (no cancellation for small spheres).
float sphereOneMinusCos(float r2, float d2) {
    const float sin2 = r2 / d2;
    return sin2 / (1.0f + std::sqrt(std::max(0.0f, 1.0f - sin2)));
}

} // namespace

LightConstants deriveLightConstants(const scene::Light& light) {
    LightConstants c;
    c.type = light.type;
    // A muted light (LightMix) emits nothing but stays in the set: selection and the draws of
    // every path stay those of the unmuted scene.
    const glm::vec3 power = light.muted ? glm::vec3(0.0f) : light.color * light.intensity;
    c.position = light.position;
    const float len = glm::length(light.direction);
    if (len > 0.0f) c.normal = light.direction / len;
    switch (light.type) {
    case scene::LightType::Sphere:
        if (light.radius > 0.0f) {
            c.radius = light.radius;
            c.emission = power * float(1.0 / (4.0 * kPiD * kPiD * double(c.radius) * c.radius));
            break;
        }
        c.type = scene::LightType::Point; // r = 0: a point light of the same power
        [[fallthrough]];
    case scene::LightType::Point:
        c.delta = true;
        c.emission = power * float(1.0 / (4.0 * kPiD));
        break;
    case scene::LightType::Spot: {
        c.delta = true;
        c.emission = power * float(1.0 / (4.0 * kPiD));
        const double toRad = kPiD / 180.0;
        c.cosInner = float(std::cos(double(light.coneInnerDeg) * toRad));
        c.cosOuter = float(std::cos(double(light.coneOuterDeg) * toRad));
        break;
    }
    case scene::LightType::Rect: {
        const glm::vec3 ref = std::abs(c.normal.y) > kVerticalNormal ? glm::vec3(0.0f, 0.0f, 1.0f)
                                                                    : glm::vec3(0.0f, 1.0f, 0.0f);
        const glm::vec3 u = glm::normalize(glm::cross(ref, c.normal));
        const glm::vec3 v = glm::cross(c.normal, u);
        c.axisU = u * (0.5f * light.size.x);
        c.axisV = v * (0.5f * light.size.y);
        c.area = light.size.x * light.size.y;
        if (c.area > 0.0f) c.emission = power * float(1.0 / (kPiD * double(c.area)));
        break;
    }
    case scene::LightType::Sun: {
        const double halfAngle = 0.5 * double(light.angularDiameterDeg) * kPiD / 180.0;
        if (halfAngle <= 0.0) {
            c.delta = true;
            c.emission = power; // irradiance at normal incidence
            break;
        }
        const double s = std::sin(halfAngle), sHalf = std::sin(0.5 * halfAngle);
        c.sin2Sun = float(s * s);
        c.oneMinusCosSun = float(2.0 * sHalf * sHalf);
        c.emission = power * float(1.0 / (kPiD * s * s));
        break;
    }
    }
    return c;
}

LightSampler::LightSampler(const scene::Light& light) : m_c(deriveLightConstants(light)) {}

LightSample LightSampler::sample(const glm::vec3& p, float u1, float u2) const {
    switch (m_c.type) {
    case scene::LightType::Sphere: return sampleSphere(p, u1, u2);
    case scene::LightType::Rect: return sampleRect(p, u1, u2);
    case scene::LightType::Sun: return sampleSun(u1, u2);
    case scene::LightType::Point:
    case scene::LightType::Spot: break;
    }
    LightSample s;
    const glm::vec3 toLight = m_c.position - p;
    const float d2 = glm::dot(toLight, toLight);
    if (!(d2 > kMinDistance2)) return s;
    s.distance = std::sqrt(d2);
    s.wi = toLight / s.distance;
    s.value = m_c.emission / d2;
    if (m_c.type == scene::LightType::Spot) s.value *= spotFalloff(-s.wi);
    s.pdf = 1.0f;
    s.delta = true;
    s.valid = true;
    return s;
}

LightSample LightSampler::sampleSphere(const glm::vec3& p, float u1, float u2) const {
    LightSample s;
    const glm::vec3 toCentre = m_c.position - p;
    const float d2 = glm::dot(toCentre, toCentre), r2 = m_c.radius * m_c.radius;
    if (!(d2 > r2)) return s; // inside: the surface emits outward only
    const float oneMinusCos = sphereOneMinusCos(r2, d2);
    if (!(oneMinusCos > 0.0f)) return s;
    const float d = std::sqrt(d2);
    float sin2 = 0.0f;
    s.wi = sampleCone(toCentre / d, oneMinusCos, u1, u2, sin2);
    // First intersection along wi: t = D cos θ − sqrt(r² − D² sin²θ).
    const float cosTheta = 1.0f - u1 * oneMinusCos;
    s.distance = std::max(0.0f, d * cosTheta - std::sqrt(std::max(0.0f, r2 - d2 * sin2)));
    s.value = m_c.emission;
    s.pdf = conePdf(oneMinusCos);
    s.valid = true;
    return s;
}

SphericalRect LightSampler::sphericalRect(const glm::vec3& p) const {
    return SphericalRect(m_c.position - m_c.axisU - m_c.axisV, 2.0f * m_c.axisU, 2.0f * m_c.axisV, p);
}

LightSample LightSampler::sampleRect(const glm::vec3& p, float u1, float u2) const {
    LightSample s;
    if (!(m_c.area > 0.0f) || !(glm::dot(p - m_c.position, m_c.normal) > 0.0f)) return s; // back side
    const SphericalRect sr = sphericalRect(p);
    const bool spherical = sr.solidAngle() >= kMinSphericalRectSolidAngle;
    const glm::vec3 q = spherical ? sr.samplePoint({u1, u2})
                                  : m_c.position + (2.0f * u1 - 1.0f) * m_c.axisU +
                                        (2.0f * u2 - 1.0f) * m_c.axisV;
    const glm::vec3 toPoint = q - p;
    const float d2 = glm::dot(toPoint, toPoint);
    if (!(d2 > 0.0f)) return s;
    const float d = std::sqrt(d2);
    const glm::vec3 wi = toPoint / d;
    const float cosLight = -glm::dot(wi, m_c.normal);
    if (!(cosLight > 0.0f)) return s; // the back face emits nothing
    s.wi = wi;
    s.distance = d;
    s.value = m_c.emission;
    s.pdf = spherical ? 1.0f / sr.solidAngle() : d2 / (m_c.area * cosLight);
    s.valid = std::isfinite(s.pdf);
    return s;
}

LightSample LightSampler::sampleSun(float u1, float u2) const {
    LightSample s;
    s.distance = kInfinity;
    s.value = m_c.emission;
    s.valid = true;
    if (m_c.delta) {
        s.wi = -m_c.normal;
        s.pdf = 1.0f;
        s.delta = true;
        return s;
    }
    float sin2 = 0.0f;
    s.wi = sampleCone(-m_c.normal, m_c.oneMinusCosSun, u1, u2, sin2);
    s.pdf = conePdf(m_c.oneMinusCosSun);
    return s;
}

float LightSampler::spotFalloff(const glm::vec3& fromLight) const {
    const float cosAlpha = glm::dot(fromLight, m_c.normal);
    if (!(m_c.cosInner > m_c.cosOuter)) return cosAlpha >= m_c.cosOuter ? 1.0f : 0.0f;
    const float t = std::clamp((cosAlpha - m_c.cosOuter) / (m_c.cosInner - m_c.cosOuter), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

float LightSampler::pdf(const glm::vec3& p, const glm::vec3& wi) const {
    if (m_c.delta) return 0.0f;
    switch (m_c.type) {
    case scene::LightType::Sphere: {
        const glm::vec3 toCentre = m_c.position - p;
        const float d2 = glm::dot(toCentre, toCentre), r2 = m_c.radius * m_c.radius;
        if (!(d2 > r2)) return 0.0f;
        const float b = glm::dot(toCentre, wi);
        const glm::vec3 perp = toCentre - b * wi;
        if (b <= 0.0f || glm::dot(perp, perp) > r2 * kRimSlack2) return 0.0f;
        return conePdf(sphereOneMinusCos(r2, d2));
    }
    case scene::LightType::Rect: {
        auto hit = evalHit(p, wi);
        if (!hit) return 0.0f;
        const SphericalRect sr = sphericalRect(p);
        if (sr.solidAngle() >= kMinSphericalRectSolidAngle) return 1.0f / sr.solidAngle();
        return hit->distance * hit->distance / (m_c.area * -glm::dot(wi, m_c.normal));
    }
    case scene::LightType::Sun: {
        const glm::vec3 toSun = -m_c.normal;
        const glm::vec3 c = glm::cross(wi, toSun);
        if (glm::dot(wi, toSun) <= 0.0f || glm::dot(c, c) > m_c.sin2Sun * kRimSlack2) return 0.0f;
        return conePdf(m_c.oneMinusCosSun);
    }
    case scene::LightType::Point:
    case scene::LightType::Spot: break;
    }
    return 0.0f;
}

std::optional<LightHit> LightSampler::evalHit(const glm::vec3& origin, const glm::vec3& dir,
                                              float tMax) const {
    if (m_c.delta) return std::nullopt;
    switch (m_c.type) {
    case scene::LightType::Sphere: {
        const glm::vec3 toCentre = m_c.position - origin;
        const float d2 = glm::dot(toCentre, toCentre), r2 = m_c.radius * m_c.radius;
        if (!(d2 > r2)) return std::nullopt;
        const float b = glm::dot(toCentre, dir);
        const glm::vec3 perp = toCentre - b * dir;
        const float h2 = r2 - glm::dot(perp, perp);
        if (b <= 0.0f || h2 < r2 * (1.0f - kRimSlack2)) return std::nullopt;
        const float t = b - std::sqrt(std::max(0.0f, h2));
        if (!(t > 0.0f && t < tMax)) return std::nullopt;
        return LightHit{t, m_c.emission};
    }
    case scene::LightType::Rect: {
        if (!(m_c.area > 0.0f)) return std::nullopt;
        const float facing = glm::dot(dir, m_c.normal);
        if (!(facing < 0.0f)) return std::nullopt; // parallel, or seeing the back face
        const float t = glm::dot(m_c.position - origin, m_c.normal) / facing;
        if (!(t > 0.0f && t < tMax)) return std::nullopt;
        const glm::vec3 local = origin + t * dir - m_c.position;
        const float a = glm::dot(local, m_c.axisU) / glm::dot(m_c.axisU, m_c.axisU);
        const float b = glm::dot(local, m_c.axisV) / glm::dot(m_c.axisV, m_c.axisV);
        if (std::abs(a) > kEdgeSlack || std::abs(b) > kEdgeSlack) return std::nullopt;
        return LightHit{t, m_c.emission};
    }
    case scene::LightType::Sun: {
        if (tMax != kInfinity || pdf(origin, dir) <= 0.0f) return std::nullopt;
        return LightHit{kInfinity, m_c.emission};
    }
    case scene::LightType::Point:
    case scene::LightType::Spot: break;
    }
    return std::nullopt;
}

} // namespace wavelit::render
