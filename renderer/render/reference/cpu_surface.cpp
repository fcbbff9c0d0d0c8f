#include "render/reference/cpu_surface.h"

#include <glm/geometric.hpp>

namespace wavelit::render {
namespace {
glm::vec3 vec3Of(const float* v) { return glm::vec3(v[0], v[1], v[2]); }
} // namespace

SurfacePoint surfaceAt(const scene::Bvh& bvh, const scene::BvhHit& hit, const glm::vec3& origin,
                       const glm::vec3& dir) {
    const scene::BvhTriangle& tri = bvh.triangles[hit.triangle];
    SurfacePoint s;
    s.position = origin + hit.t * dir;
    s.materialIndex = tri.v0[3];
    // Two-sided: the geometric normal faces the incoming ray.
    glm::vec3 p0 = vec3Of(tri.v0), p1 = vec3Of(tri.v1), p2 = vec3Of(tri.v2);
    glm::vec3 ng = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    if (glm::dot(ng, dir) > 0.0f) ng = -ng;
    float b0 = 1.0f - hit.b1 - hit.b2;
    glm::vec3 ns = b0 * vec3Of(tri.n0) + hit.b1 * vec3Of(tri.n1) + hit.b2 * vec3Of(tri.n2);
    float length = glm::length(ns);
    ns = length > 0.0f ? ns / length : ng; // opposing vertex normals can cancel
    if (glm::dot(ns, ng) < 0.0f) ns = -ns;
    // A shading normal that hides the viewer would give wo.z <= 0 in the local frame, where the
    // BRDFs are zero: fall back to the true surface.
    if (glm::dot(-dir, ns) <= 0.0f) ns = ng;
    s.geometric = ng;
    s.shading = ns;
    return s;
}

} // namespace wavelit::render
