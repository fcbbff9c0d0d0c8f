// Direction samplers on the local hemisphere (z = normal) that every BRDF and the `uniform` /
// `cosine` samplers of architecture.md §5.B share. Each has sample, pdf and invert (pbrt style) so tests
// can round-trip; pdfs are in SOLID ANGLE (sr^-1), inputs u in [0,1)^2.
//
// The cosine sampler goes through Shirley–Chiu's concentric disk map: it keeps stratification
// (area-preserving, low distortion), and the GLSL twin (plugins/lambert.glsl) uses the same map so
// the CPU and GPU tracers turn the same (u1, u2) into the same direction.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace wavelit::util {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;

// Unit square -> unit disk, area preserving (pdf on the disk = 1/π).
glm::vec2 sampleConcentricDisk(glm::vec2 u);
glm::vec2 invertConcentricDisk(glm::vec2 p);

// Cosine-weighted: pdf = cosθ/π on z > 0, 0 elsewhere.
glm::vec3 sampleCosineHemisphere(glm::vec2 u);
float cosineHemispherePdf(const glm::vec3& w);
glm::vec2 invertCosineHemisphere(const glm::vec3& w);

// Uniform: pdf = 1/(2π) on z > 0, 0 elsewhere. z = u.x, φ = 2π u.y.
glm::vec3 sampleUniformHemisphere(glm::vec2 u);
float uniformHemispherePdf(const glm::vec3& w);
glm::vec2 invertUniformHemisphere(const glm::vec3& w);

// Orthonormal basis (t, b, n) from a unit normal, branchless (Duff et al. 2017, JCGT 6(1)).
// The GPU tracer builds its shading frame the same way, so local directions agree bit for bit
// up to float rounding.
struct Frame {
    glm::vec3 t, b, n;
    static Frame fromNormal(const glm::vec3& n);
    // Inline: the relighting preview and the samplers call these per direction in inner loops.
    glm::vec3 toLocal(const glm::vec3& w) const {
        return glm::vec3(t.x * w.x + t.y * w.y + t.z * w.z, b.x * w.x + b.y * w.y + b.z * w.z,
                         n.x * w.x + n.y * w.y + n.z * w.z);
    }
    glm::vec3 toWorld(const glm::vec3& w) const { return w.x * t + w.y * b + w.z * n; }
};

} // namespace wavelit::util
