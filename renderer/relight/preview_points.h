// The preview points: one per pixel of a preview-resolution G-buffer, the primary hit of the
// scene camera's ray through the pixel centre (docs/relighting.md says why pixels, not vertices:
// a 2-triangle ground has no vertices to hold a shadow). The camera and surface rules are
// docs/estimator.md's "Camera" and "Surfaces" (the path tracer's), so the preview shades the
// point the reference image shows at that pixel.
#pragma once

#include "scene/bvh.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace wavelit::relight {

struct PreviewPoint {
    bool hit = false;
    glm::vec3 position{0.0f};
    glm::vec3 geometric{0.0f}; // n_g, facing the camera
    glm::vec3 shading{0.0f};   // n_s (n_g when the viewer is behind it)
    glm::vec3 wo{0.0f};        // toward the camera (unit); for a miss, the ray direction's opposite
    uint32_t object = 0;       // index into Scene::objects
    uint32_t material = 0;     // index into Scene::materials (== size: the default Material{})
    float distance = 0.0f;     // along the camera ray to the hit (infinity for a miss)
    bool backFace = false;     // n_g is the triangle's winding normal negated (seen from behind)

    bool operator==(const PreviewPoint&) const = default;
};

// The camera's ray directions for a width x height image (the basis computed once).
class CameraRays {
public:
    CameraRays(const scene::Camera& camera, int width, int height);
    // Unit direction through pixel (x, y) at offset (u, v) in [0,1)^2 inside it (0.5, 0.5: the
    // centre, where the preview points are).
    glm::vec3 direction(int x, int y, float u = 0.5f, float v = 0.5f) const;

private:
    glm::vec3 m_forward, m_right, m_up;
    float m_tanHalf, m_aspect;
    int m_width, m_height;
};

// The point of pixel (x, y); `bvh` is buildBvh(scene).
PreviewPoint castPreviewPoint(const scene::Scene& scene, const scene::Bvh& bvh, int width, int height,
                              int x, int y);
// Row-major, width * height points.
std::vector<PreviewPoint> castPreviewPoints(const scene::Scene& scene, const scene::Bvh& bvh,
                                            int width, int height, int threads);

} // namespace wavelit::relight
