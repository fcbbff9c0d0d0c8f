#include "relight/preview_points.h"

#include "util/parallel_for.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <utility>
#include <limits>

namespace wavelit::relight {
namespace {
glm::vec3 vec3Of(const float* v) { return glm::vec3(v[0], v[1], v[2]); }
} // namespace

CameraRays::CameraRays(const scene::Camera& camera, int width, int height)
    : m_width(width), m_height(height) {
    m_forward = glm::normalize(camera.target - camera.position);
    m_right = glm::normalize(glm::cross(m_forward, camera.up));
    m_up = glm::cross(m_right, m_forward);
    m_tanHalf = std::tan(0.5f * camera.verticalFovDeg * 3.14159265358979323846f / 180.0f);
    m_aspect = float(width) / float(height);
}

glm::vec3 CameraRays::direction(int x, int y, float u, float v) const {
    const float sx = (2.0f * (float(x) + u) / float(m_width) - 1.0f) * m_tanHalf * m_aspect;
    const float sy = (1.0f - 2.0f * (float(y) + v) / float(m_height)) * m_tanHalf;
    return glm::normalize(m_forward + sx * m_right + sy * m_up);
}

namespace {
PreviewPoint castRay(const scene::Scene& scene, const scene::Bvh& bvh, const glm::vec3& dir) {
    const glm::vec3 origin = scene.camera.position;
    PreviewPoint p;
    p.wo = -dir;
    p.distance = std::numeric_limits<float>::infinity();
    scene::BvhHit hit;
    if (!scene::intersect(bvh, origin, dir, 0.0f, std::numeric_limits<float>::max(), hit)) return p;
    p.distance = hit.t;
    const scene::BvhTriangle& tri = bvh.triangles[hit.triangle];
    p.hit = true;
    p.position = origin + hit.t * dir;
    p.material = uint32_t(tri.v0[3]);
    p.object = uint32_t(tri.v1[3]);
    // docs/estimator.md "Surfaces", as the reference tracer's surfaceAt.
    const glm::vec3 p0 = vec3Of(tri.v0), p1 = vec3Of(tri.v1), p2 = vec3Of(tri.v2);
    glm::vec3 ng = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    if (glm::dot(ng, dir) > 0.0f) {
        ng = -ng;
        p.backFace = true;
    }
    const float b0 = 1.0f - hit.b1 - hit.b2;
    glm::vec3 ns = b0 * vec3Of(tri.n0) + hit.b1 * vec3Of(tri.n1) + hit.b2 * vec3Of(tri.n2);
    const float length = glm::length(ns);
    ns = length > 0.0f ? ns / length : ng;
    if (glm::dot(ns, ng) < 0.0f) ns = -ns;
    if (glm::dot(-dir, ns) <= 0.0f) ns = ng;
    p.geometric = ng;
    p.shading = ns;
    return p;
}
} // namespace

PreviewPoint castPreviewPoint(const scene::Scene& scene, const scene::Bvh& bvh, int width, int height,
                              int x, int y) {
    const CameraRays rays(scene.camera, width, height);
    PreviewPoint p = castRay(scene, bvh, rays.direction(x, y));
    if (p.hit) return p;
    // A centre ray can pass exactly through the line where two objects meet (the Cornell box's
    // wall-ceiling edges, on the image diagonal of its symmetric camera), which the ray-triangle
    // test does not treat as watertight: it misses both and the pixel shows the environment,
    // where the tracer's jittered rays all hit a wall. When three of the four quarter-pixel rays
    // hit, the pixel is geometry and takes the first of them; a true silhouette (about half)
    // stays a miss.
    int hits = 0;
    PreviewPoint first;
    for (const auto& [u, v] : {std::pair{0.25f, 0.25f}, {0.75f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f}}) {
        PreviewPoint q = castRay(scene, bvh, rays.direction(x, y, u, v));
        if (!q.hit) continue;
        if (hits++ == 0) first = q;
    }
    return hits >= 3 ? first : p;
}

std::vector<PreviewPoint> castPreviewPoints(const scene::Scene& scene, const scene::Bvh& bvh,
                                            int width, int height, int threads) {
    std::vector<PreviewPoint> points(size_t(width) * size_t(height));
    util::parallelFor(points.size(), threads, [&](size_t i) {
        points[i] = castPreviewPoint(scene, bvh, width, height, int(i % size_t(width)), int(i / size_t(width)));
    });
    return points;
}

} // namespace wavelit::relight
