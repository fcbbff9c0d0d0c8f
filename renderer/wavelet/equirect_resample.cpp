#include "wavelet/equirect_resample.h"

#include "util/check.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::wavelet {
namespace {

constexpr double kPi = std::numbers::pi;
// Sub-cells per target texel aimed for where source texels are coarse: 4 keeps every target
// texel hit with margin (at least 2 x 2 sub-cells of the largest source texel per target texel).
constexpr double kSubcellsPerTarget = 4.0;
constexpr int kMaxSubdivision = 64;

// Solid angle of the latitude band between polar angles theta0 < theta1 over azimuth width dphi.
double bandSolidAngle(double theta0, double theta1, double dphi) {
    return dphi * (std::cos(theta0) - std::cos(theta1));
}

} // namespace

glm::dvec3 equirectEnergy(const util::ImageRGB& env) {
    glm::dvec3 e(0.0);
    const double dphi = 2.0 * kPi / env.width;
    for (int y = 0; y < env.height; ++y) {
        const double omega = bandSolidAngle(kPi * y / env.height, kPi * (y + 1) / env.height, dphi);
        for (int x = 0; x < env.width; ++x)
            e += glm::dvec3(env.at(x, y)) * omega;
    }
    return e;
}

glm::dvec3 faceEnergy(const std::vector<util::ImageRGB>& faces, const SphereMap& map) {
    glm::dvec3 e(0.0);
    for (int f = 0; f < int(faces.size()); ++f) {
        const int side = faces[size_t(f)].width;
        int n = 0;
        while ((1 << n) < side)
            ++n;
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                e += glm::dvec3(faces[size_t(f)].at(x, y)) * map.texelSolidAngle(f, n, x, y);
    }
    return e;
}

std::vector<util::ImageRGB> resampleEquirect(const util::ImageRGB& env, const SphereMap& map,
                                             int n) {
    WAVELIT_CHECK(!env.empty() && n >= 0);
    const int faces = map.faceCount(), side = 1 << n;
    std::vector<std::vector<glm::dvec3>> energy(
        size_t(faces), std::vector<glm::dvec3>(size_t(side) * side, glm::dvec3(0.0)));
    const double targetOmega = 4.0 * kPi / (faces * double(side) * side);
    const double dphi = 2.0 * kPi / env.width;
    for (int y = 0; y < env.height; ++y) {
        const double theta0 = kPi * y / env.height, theta1 = kPi * (y + 1) / env.height;
        const double sourceOmega = bandSolidAngle(theta0, theta1, dphi);
        const int s =
            std::clamp(int(std::ceil(std::sqrt(kSubcellsPerTarget * sourceOmega / targetOmega))), 1,
                       kMaxSubdivision);
        for (int j = 0; j < s; ++j) {
            const double ta = theta0 + (theta1 - theta0) * j / s,
                         tb = theta0 + (theta1 - theta0) * (j + 1) / s;
            const double subOmega = bandSolidAngle(ta, tb, dphi / s);
            const double theta = 0.5 * (ta + tb);
            const double sinT = std::sin(theta), cosT = std::cos(theta);
            for (int x = 0; x < env.width; ++x) {
                const glm::dvec3 radiance(env.at(x, y));
                if (radiance == glm::dvec3(0.0))
                    continue;
                for (int i = 0; i < s; ++i) {
                    const double u = (x + (i + 0.5) / s) / env.width;
                    const double phi =
                        2.0 * kPi * (u - 0.5); // inverse of u = 0.5 + atan2(z, x) / 2 pi
                    const glm::dvec3 d(sinT * std::cos(phi), cosT, sinT * std::sin(phi));
                    const FacePoint p = map.toSquare(d);
                    const int tx = std::min(int(p.uv.x * side), side - 1);
                    const int ty = std::min(int(p.uv.y * side), side - 1);
                    energy[size_t(p.face)][size_t(ty) * side + tx] += radiance * subOmega;
                }
            }
        }
    }
    std::vector<util::ImageRGB> out;
    for (int f = 0; f < faces; ++f) {
        util::ImageRGB img(side, side);
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                img.at(x, y) = glm::vec3(energy[size_t(f)][size_t(y) * side + x] /
                                         map.texelSolidAngle(f, n, x, y));
        out.push_back(std::move(img));
    }
    return out;
}

} // namespace wavelit::wavelet
