#include "wavelet/sphere_map.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::wavelet {
namespace {

constexpr double kPi = std::numbers::pi;

// Face frames of the cube map: major axis, then the directions of +a and +b.
struct Face {
    glm::dvec3 major, a, b;
};
const Face kFaces[6] = {
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},   {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},
};

// Solid angle of the face rectangle [0,a] x [0,b] at unit distance (signed).
double cornerSolidAngle(double a, double b) {
    return std::atan2(a * b, std::sqrt(a * a + b * b + 1.0));
}

} // namespace

// Clarberg 2008, with the map's z axis as our +Y (up) and its (x, y) as our (x, z).
glm::dvec3 OctahedralMap::toDirection(int, glm::dvec2 uv) const {
    const double u = 2.0 * uv.x - 1.0, v = 2.0 * uv.y - 1.0;
    const double up = std::abs(u), vp = std::abs(v);
    const double sd = 1.0 - (up + vp);
    const double r = 1.0 - std::abs(sd);
    const double phi = (r == 0.0 ? 1.0 : (vp - up) / r + 1.0) * (kPi / 4.0);
    const double z = std::copysign(1.0 - r * r, sd);
    const double s = r * std::sqrt(std::max(0.0, 2.0 - r * r));
    const double x = std::copysign(std::cos(phi), u) * s;
    const double y = std::copysign(std::sin(phi), v) * s;
    return {x, z, y};
}

// pbrt-v4's EqualAreaSphereToSquare (the inverse of the above).
FacePoint OctahedralMap::toSquare(glm::dvec3 direction) const {
    const glm::dvec3 d = glm::normalize(direction);
    const double dx = d.x, dy = d.z, dz = d.y; // back to the map's axes
    const double x = std::abs(dx), y = std::abs(dy), z = std::abs(dz);
    const double r = std::sqrt(std::max(0.0, 1.0 - z));
    const double a = std::max(x, y);
    double b = std::min(x, y);
    b = a == 0.0 ? 0.0 : b / a;
    double phi = std::atan(b) * (2.0 / kPi);
    if (x < y)
        phi = 1.0 - phi;
    double v = phi * r, u = r - v;
    if (dz < 0.0) {
        std::swap(u, v);
        u = 1.0 - u;
        v = 1.0 - v;
    }
    u = std::copysign(u, dx);
    v = std::copysign(v, dy);
    return {0, {std::clamp(0.5 * (u + 1.0), 0.0, 1.0), std::clamp(0.5 * (v + 1.0), 0.0, 1.0)}};
}

double OctahedralMap::jacobian(int, glm::dvec2) const {
    return 4.0 * kPi;
}

double OctahedralMap::texelSolidAngle(int, int n, int, int) const {
    return std::ldexp(4.0 * kPi, -2 * n);
}

glm::dvec3 CubeMap::toDirection(int face, glm::dvec2 uv) const {
    const Face& f = kFaces[face];
    return glm::normalize(f.major + (2.0 * uv.x - 1.0) * f.a + (2.0 * uv.y - 1.0) * f.b);
}

FacePoint CubeMap::toSquare(glm::dvec3 d) const {
    const glm::dvec3 ad = glm::abs(d);
    int face;
    if (ad.x >= ad.y && ad.x >= ad.z)
        face = d.x >= 0.0 ? 0 : 1;
    else if (ad.y >= ad.z)
        face = d.y >= 0.0 ? 2 : 3;
    else
        face = d.z >= 0.0 ? 4 : 5;
    const Face& f = kFaces[face];
    const double m = glm::dot(d, f.major);
    const double a = glm::dot(d, f.a) / m, b = glm::dot(d, f.b) / m;
    return {face, {std::clamp(0.5 * (a + 1.0), 0.0, 1.0), std::clamp(0.5 * (b + 1.0), 0.0, 1.0)}};
}

double CubeMap::jacobian(int, glm::dvec2 uv) const {
    const double a = 2.0 * uv.x - 1.0, b = 2.0 * uv.y - 1.0;
    return 4.0 / std::pow(1.0 + a * a + b * b, 1.5);
}

double CubeMap::texelSolidAngle(int, int n, int x, int y) const {
    const double step = std::ldexp(2.0, -n);
    const double a0 = -1.0 + x * step, a1 = a0 + step, b0 = -1.0 + y * step, b1 = b0 + step;
    return cornerSolidAngle(a1, b1) - cornerSolidAngle(a0, b1) - cornerSolidAngle(a1, b0) +
           cornerSolidAngle(a0, b0);
}

} // namespace wavelit::wavelet
