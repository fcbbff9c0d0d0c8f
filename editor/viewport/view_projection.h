// ViewProjection: the render camera's pinhole model in the viewport image's pixel coordinates
// (x right, y down, (0, 0) the top-left corner of the image, (W, H) the bottom-right), the same
// model as the tracers' camera rays (relight/preview_points.h CameraRays: vertical fov, aspect
// W/H, +Y up, architecture.md §3). Picking casts rays through it; the gizmos project handles and
// turn mouse motion into world motion with it.
#pragma once

#include "scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace wavelit::editor {

struct ViewRay {
    glm::vec3 origin;
    glm::vec3 direction; // unit
};

class ViewProjection {
public:
    ViewProjection(const scene::Camera& camera, int imageWidth, int imageHeight);

    // The ray through image point (x, y) (pixel centres are at +0.5).
    ViewRay ray(glm::vec2 pixel) const;
    // The image point of a world point; nullopt behind (or on) the camera plane.
    std::optional<glm::vec2> project(const glm::vec3& world) const;
    // Depth of a world point along the view direction (> 0 in front of the camera).
    float depth(const glm::vec3& world) const;
    // World length of one image pixel at `depth` (for screen-sized handles and drag scaling).
    float worldPerPixel(float depth) const;

    const glm::vec3& forward() const { return m_forward; }
    const glm::vec3& right() const { return m_right; }
    const glm::vec3& up() const { return m_up; }
    const glm::vec3& position() const { return m_position; }
    int width() const { return m_width; }
    int height() const { return m_height; }

private:
    glm::vec3 m_position, m_forward, m_right, m_up;
    float m_tanHalf, m_aspect;
    int m_width, m_height;
};

// The point where `ray` meets the plane through `point` with normal `normal`; nullopt when the ray
// is (nearly) parallel to the plane or the plane is behind the ray's origin.
std::optional<glm::vec3> intersectPlane(const ViewRay& ray, const glm::vec3& point, const glm::vec3& normal);

} // namespace wavelit::editor
