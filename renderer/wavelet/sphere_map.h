// Sphere parameterisations on 2^n x 2^n squares (architecture.md §3), behind one interface so tables,
// products and samplers do not care which is used.
//
//  - OctahedralMap (default): Clarberg 2008's equal-area octahedral map, one square for the whole
//    sphere with constant Jacobian 4 pi: a square-domain pdf times 1/(4 pi) is the solid-angle pdf,
//    and products need no Jacobian factor. +Y (up) maps to the square's centre, -Y to its corners.
//  - CubeMap: the paper's choice, six faces (0..5: +X -X +Y -Y +Z -Z, OpenGL-like orientation),
//    each its own square; Jacobian 4 / (1 + a^2 + b^2)^1.5 with (a, b) = 2 uv - 1, so a product
//    sampled per face must carry the Jacobian as one extra factor.
// Points: (face, uv) with uv in [0,1]^2, v down the image rows. Jacobian = d(solid angle)/d(uv
// area).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace wavelit::wavelet {

struct FacePoint {
    int face = 0;
    glm::dvec2 uv{0.0};
};

class SphereMap {
public:
    virtual ~SphereMap() = default;
    virtual int faceCount() const = 0;
    virtual glm::dvec3 toDirection(int face, glm::dvec2 uv) const = 0; // unit vector
    virtual FacePoint toSquare(glm::dvec3 direction) const = 0;        // any non-zero vector
    virtual double jacobian(int face, glm::dvec2 uv) const = 0;
    // Exact solid angle of texel (x, y) of a 2^n grid on `face`.
    virtual double texelSolidAngle(int face, int n, int x, int y) const = 0;
};

class OctahedralMap final : public SphereMap {
public:
    int faceCount() const override { return 1; }
    glm::dvec3 toDirection(int face, glm::dvec2 uv) const override;
    FacePoint toSquare(glm::dvec3 direction) const override;
    double jacobian(int face, glm::dvec2 uv) const override;
    double texelSolidAngle(int face, int n, int x, int y) const override;
};

class CubeMap final : public SphereMap {
public:
    int faceCount() const override { return 6; }
    glm::dvec3 toDirection(int face, glm::dvec2 uv) const override;
    FacePoint toSquare(glm::dvec3 direction) const override;
    double jacobian(int face, glm::dvec2 uv) const override;
    double texelSolidAngle(int face, int n, int x, int y) const override;
};

} // namespace wavelit::wavelet
