// Next-event estimation of one analytic light (scene.h: Point, Sphere, Rect, Spot, Sun): sample a
// direction toward the light from a shading point, the pdf of any direction in SOLID ANGLE (for
// MIS with BSDF-sampled rays), and the emission a ray finds when it crosses the light. The CPU
// reference tracer and docs/estimator.md ("Analytic lights") use exactly these formulas; the GPU
// shader is their twin.
//
// Units (scene.h: `intensity` × `color`), derived once here:
//   Point:  radiant power Φ W, isotropic: intensity I = Φ/(4π) W/sr.
//   Spot:   I = Φ/(4π) × smoothstep falloff in cos α between the outer and inner half angles
//           (α: angle between `direction` and the ray from the light), 1 inside the inner cone,
//           0 outside the outer one; equal angles give a hard edge.
//   Sphere: Lambertian surface of radius r emitting Φ: exitance πL over area 4πr², so
//           L = Φ/(4π² r²) W/(m² sr). Seen from outside it subtends a cone with sin θmax = r/D
//           and gives irradiance E = L π sin²θmax cos θ = Φ cos θ/(4π D²) (cone above the
//           horizon) — exactly the point light of the same power. r = 0 is a point light.
//   Rect:   Lambertian front face (the side `direction` points to) of area A = w·h emitting Φ:
//           L = Φ/(π A). Axes: width along U = normalize(cross(ref, n)), height along
//           V = cross(n, U), ref = +Y unless |n.y| > 0.999, then +Z (n = `direction`).
//   Sun:    irradiance E W/m² on a plane facing it, uniform radiance over a cone of half angle
//           θs = d/2 around −`direction`. ∫cone L cos θ dω = L π sin²θs exactly, so
//           L = E/(π sin²θs); the cone's solid angle is Ω = 2π(1 − cos θs) = 4π sin²(θs/2).
//           d = 0 is a delta directional light of irradiance E.
//
// Sampling: Sphere uniformly in the visible cone (pdf 1/Ω_cone), Rect uniformly in the solid angle
// it subtends (light_spherical_rect.h, pdf 1/S) or, where S < 1e-2 sr, uniformly by area
// (pdf d²/(A cos θ_light)), Sun uniformly in its cone (pdf 1/Ω); Point and Spot are delta lights
// (pdf reported as 1, flagged). Small cones are handled through sin² and 1 − cos computed without
// cancellation, so a 0.53° sun keeps its exact solid angle in float.
// Immutable after construction; safe to share between threads.
#pragma once

#include "render/lights/light_spherical_rect.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <limits>
#include <optional>

namespace wavelit::render {

struct LightSample {
    glm::vec3 wi{0.0f};      // unit, from the shading point toward the light
    float distance = 0.0f;   // to the sampled point: shadow-ray length (infinity for the sun)
    // Area lights (Sphere, Rect, Sun with d > 0): emitted radiance L toward the point.
    // Delta lights (Point, Spot, Sun with d = 0): irradiance at normal incidence, I/D² or E.
    glm::vec3 value{0.0f};
    float pdf = 0.0f;        // solid angle; 1 for delta lights
    bool delta = false;
    bool valid = false;
};

struct LightHit {
    float distance = 0.0f;   // along the ray (infinity for the sun)
    glm::vec3 radiance{0.0f};
};

// The constants every light's sampling and evaluation derive from the scene's physical units
// (docs/estimator.md "Analytic lights"). Computed once here and shared by LightSampler (CPU) and
// the GPU light packing (gpu_scene_data.cpp), so both tracers see bit-identical values.
struct LightConstants {
    scene::LightType type = scene::LightType::Point; // a Sphere of radius 0 becomes a Point
    bool delta = false;
    glm::vec3 emission{0.0f}; // area lights: radiance; point/spot: I = Φ/(4π); delta sun: E
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, -1.0f, 0.0f}; // `direction`, normalised: the way light travels
    glm::vec3 axisU{1.0f, 0.0f, 0.0f}, axisV{0.0f, 0.0f, 1.0f}; // Rect: half extents × axes
    float radius = 0.0f;
    float area = 0.0f;
    float cosInner = 1.0f, cosOuter = 1.0f;     // Spot
    float sin2Sun = 0.0f, oneMinusCosSun = 0.0f; // Sun: sin²θs and 1 − cos θs
};

LightConstants deriveLightConstants(const scene::Light& light);

class LightSampler {
public:
    explicit LightSampler(const scene::Light& light);

    // Direction toward the light from p, with (u1, u2) in [0,1)². Invalid when p sees nothing of
    // the light (inside a sphere light, behind a rect light, at the light's own position).
    LightSample sample(const glm::vec3& p, float u1, float u2) const;
    // Solid-angle density of sample() at direction wi (unit) from p; 0 for delta lights and for
    // directions that miss the light.
    float pdf(const glm::vec3& p, const glm::vec3& wi) const;
    // The light's emission found by a ray origin + t·dir with t in (0, tMax): the first crossing
    // of a sphere light from outside, the front face of a rect light, or the sun's cone when the
    // ray escapes (tMax = infinity). Lights are not in the BVH and do not block rays.
    std::optional<LightHit> evalHit(const glm::vec3& origin, const glm::vec3& dir,
                                    float tMax = std::numeric_limits<float>::infinity()) const;

    bool isDelta() const { return m_c.delta; }
    scene::LightType type() const { return m_c.type; }
    // Emitted radiance of area lights; I = Φ/(4π) for point/spot; E for a delta sun.
    const glm::vec3& emission() const { return m_c.emission; }

private:
    LightSample sampleSphere(const glm::vec3& p, float u1, float u2) const;
    LightSample sampleRect(const glm::vec3& p, float u1, float u2) const;
    LightSample sampleSun(float u1, float u2) const;
    SphericalRect sphericalRect(const glm::vec3& p) const;
    float spotFalloff(const glm::vec3& fromLight) const;

    LightConstants m_c;
};

} // namespace wavelit::render
