// Environment radiance lookup of the CPU reference tracer, exactly as docs/estimator.md
// "Environment" specifies (the GPU tracer's env lookup is its twin): the world direction is
// rotated by −yaw about +Y, mapped to equirect (u, v) with architecture.md §3's convention, and the
// NEAREST texel is returned — piecewise constant, so the env sampling tables (issue 6) describe
// exactly the function the tracer evaluates. No image → a constant intensity × tint.
// Immutable after construction; safe to share between threads.
#pragma once

#include "scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>

namespace wavelit::render {

class CpuEnvironment {
public:
    explicit CpuEnvironment(const scene::Environment& env);

    // Radiance arriving from world direction `dir` (unit), i.e. seen along a ray leaving the
    // scene in direction dir.
    glm::vec3 radiance(const glm::vec3& dir) const { return radianceAt(equirect(dir)); }
    // The same at equirect point uv = equirect(dir), for callers that already have it (the env
    // technique's pdf reads the same texel: one atan2 and one acos for both).
    glm::vec3 radianceAt(const glm::vec2& uv) const;

    // Equirect coordinates in [0,1]² of a world direction after the yaw rotation.
    glm::vec2 equirect(const glm::vec3& dir) const;

private:
    std::shared_ptr<const util::ImageRGB> m_image;
    glm::vec3 m_scale; // intensity × tint
    float m_cosYaw, m_sinYaw;
};

} // namespace wavelit::render
