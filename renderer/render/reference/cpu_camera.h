// Primary rays of the CPU reference tracer: docs/estimator.md "Camera", term for term, so the
// CPU and GPU tracers shoot the same ray for the same pixel and jitter.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

namespace wavelit::render {

class CpuCamera {
public:
    CpuCamera(const scene::Camera& camera, int width, int height);

    // Pixel (x, y), y = 0 the top row; jitter (u, v) in [0,1)². Returns a unit direction.
    glm::vec3 direction(int x, int y, float u, float v) const;
    const glm::vec3& origin() const { return m_origin; }

private:
    glm::vec3 m_origin, m_forward, m_right, m_up;
    float m_tanHalf, m_aspect;
    int m_width, m_height;
};

} // namespace wavelit::render
