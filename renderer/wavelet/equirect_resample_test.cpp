#include "wavelet/equirect_resample.h"
#include "wavelet/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace wavelit::wavelet {
namespace {

// Energy is accumulated in double and written as float: each texel rounds by <= 2^-24
// relative, so the total moves by at most that (plus double summation, negligible).
constexpr double kEnergyTolerance = 2.0 * 0x1p-24;

util::ImageRGB skyWithSun(int w, int h, int sunX, int sunY, float sun) {
    util::ImageRGB img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.at(x, y) = glm::vec3(0.5f + float(y) / h, 0.7f, 1.0f - 0.5f * float(x) / w);
    img.at(sunX, sunY) = glm::vec3(sun, 0.9f * sun, 0.8f * sun);
    return img;
}

void expectEnergyPreserved(const util::ImageRGB& env, const SphereMap& map, int n) {
    const glm::dvec3 before = equirectEnergy(env);
    const glm::dvec3 after = faceEnergy(resampleEquirect(env, map, n), map);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(after[c], before[c], kEnergyTolerance * before[c]) << "n " << n;
}

TEST(EquirectResample, OneTexelSunKeepsItsEnergyOctahedral) {
    OctahedralMap map;
    const util::ImageRGB env = skyWithSun(256, 128, 37, 50, 1e6f);
    for (int n : {2, 4, 6, 8})
        expectEnergyPreserved(env, map, n);
}

TEST(EquirectResample, OneTexelSunKeepsItsEnergyCube) {
    CubeMap map;
    const util::ImageRGB env = skyWithSun(128, 64, 100, 10, 1e6f);
    for (int n : {1, 3, 5})
        expectEnergyPreserved(env, map, n);
}

TEST(EquirectResample, SunLandsWhereItsDirectionMaps) {
    OctahedralMap map;
    const int w = 512, h = 256, sx = 300, sy = 60;
    const util::ImageRGB env = skyWithSun(w, h, sx, sy, 1e7f);
    const auto faces = resampleEquirect(env, map, 5);
    // Direction of the sun texel centre by architecture.md §3's mapping.
    const double phi = 2.0 * std::numbers::pi * ((sx + 0.5) / w - 0.5),
                 theta = std::numbers::pi * (sy + 0.5) / h;
    const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                       std::sin(theta) * std::sin(phi));
    const FacePoint p = map.toSquare(d);
    const int tx = int(p.uv.x * 32), ty = int(p.uv.y * 32);
    int bx = 0, by = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            if (faces[0].at(x, y).r > faces[0].at(bx, by).r)
                bx = x, by = y;
    EXPECT_LE(std::abs(bx - tx) + std::abs(by - ty), 1); // the sun texel may straddle a border
}

TEST(EquirectResample, FinerTargetThanSourceLeavesNoHoles) {
    OctahedralMap map;
    util::ImageRGB env(32, 16, glm::vec3(1.0f));
    const auto faces = resampleEquirect(env, map, 7);
    for (const glm::vec3& v : faces[0].pixels)
        EXPECT_GT(v.r, 0.0f);
}

} // namespace
} // namespace wavelit::wavelet
