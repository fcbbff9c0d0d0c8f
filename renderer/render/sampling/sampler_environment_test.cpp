// The conservative octahedral map of SamplerEnvironment (sampler_environment.cpp) against its
// definition, written out the slow way here: per octahedral texel the max of the tracer's lookup
// at 3 x 3 points, raised by a walk along each equirect texel's four edges at 16 steps per
// octahedral texel, floored at 1e-6 x the mean. The build shares each meridian between its two
// texels, reuses sines and cosines and runs rows on several threads; none of that may change a
// bit of the map, which every env pdf and product is built from.
#include "render/lights/cpu_environment.h"
#include "render/sampling/sampler_environment.h"
#include "util/image.h"
#include "util/rng.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

namespace wavelit::render {
namespace {

constexpr double kPi = std::numbers::pi;

// A sky of random texels with a 1e6 sun; odd sizes so that no row or column count is a power of
// two.
scene::Environment randomSky(int w, int h, uint64_t seed) {
    util::Pcg32 rng(seed);
    auto image = std::make_shared<util::ImageRGB>(w, h, glm::vec3(0.0f));
    for (glm::vec3& texel : image->pixels)
        texel = glm::vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
    image->at(w / 3, h / 4) = glm::vec3(1e6f);
    scene::Environment env;
    env.image = image;
    env.rotationDeg = 40.0f; // the map is env-local: the rotation must not matter
    env.intensity = 1.0f;
    return env;
}

// The map by its definition, one texel and one edge at a time, on one thread.
std::vector<double> referenceMap(const scene::Environment& env, int level) {
    const wavelet::OctahedralMap map;
    const int side = 1 << level;
    scene::Environment unrotatedEnv = env;
    unrotatedEnv.rotationDeg = 0.0f;
    const CpuEnvironment unrotated(unrotatedEnv);
    std::vector<double> grid(size_t(side) * size_t(side), 0.0);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i) {
                    const glm::dvec3 d =
                        map.toDirection(0, {(x + (i + 0.5) / 3) / side, (y + (j + 0.5) / 3) / side});
                    double& v = grid[size_t(y) * size_t(side) + size_t(x)];
                    v = std::max(v, double(util::luminance(unrotated.radiance(glm::vec3(d)))));
                }
    const util::ImageRGB& image = *env.image;
    const int w = image.width, h = image.height;
    const double cellAngle = std::sqrt(4.0 * kPi) / side;
    auto raise = [&](double theta, double phi, double value) {
        const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                           std::sin(theta) * std::sin(phi));
        const glm::dvec2 p = glm::min(map.toSquare(d).uv, glm::dvec2(0x1.fffffffffffffp-1));
        double& v = grid[size_t(std::min(int(p.y * side), side - 1)) * size_t(side) +
                         size_t(std::min(int(p.x * side), side - 1))];
        v = std::max(v, value);
    };
    for (int y = 0; y < h; ++y) {
        const double t0 = kPi * y / h, t1 = kPi * (y + 1) / h;
        const int nt = std::clamp(int(std::ceil(16 * (t1 - t0) / cellAngle)), 2, 256);
        const double arc = 2.0 * kPi / w * std::max(std::sin(t0), std::sin(t1));
        const int np = std::clamp(int(std::ceil(16 * arc / cellAngle)), 2, 256);
        for (int x = 0; x < w; ++x) {
            const double value = std::max(0.0, double(util::luminance(image.at(x, y))));
            const double p0 = 2.0 * kPi * (double(x) / w - 0.5), p1 = 2.0 * kPi * (double(x + 1) / w - 0.5);
            for (int i = 0; i <= nt; ++i) {
                raise(t0 + (t1 - t0) * i / nt, p0, value);
                raise(t0 + (t1 - t0) * i / nt, p1, value);
            }
            for (int i = 0; i <= np; ++i) {
                raise(t0, p0 + (p1 - p0) * i / np, value);
                raise(t1, p0 + (p1 - p0) * i / np, value);
            }
        }
    }
    double sum = 0.0;
    for (double v : grid) sum += v;
    for (double& v : grid) v = std::max(v, 1e-6 * sum / double(grid.size()));
    return grid;
}

TEST(SamplerEnvironment, ConservativeMapEqualsItsDefinitionForAnyThreadCount) {
    // The walk shares rows out in blocks of 64 (util/parallel_for.h): the 150-row map at a capped
    // level is three blocks, so its walk merges several workers' grids; the others are one block.
    struct Case {
        int w, h, maxLevel;
    };
    for (const Case c : {Case{37, 19, 10}, Case{64, 32, 10}, Case{91, 45, 10}, Case{203, 150, 6}}) {
        SCOPED_TRACE(testing::Message() << c.w << " x " << c.h);
        const scene::Environment env = randomSky(c.w, c.h, uint64_t(c.w) * 131u + uint64_t(c.h));
        const SamplerEnvironment one =
            SamplerEnvironment::build(env, {.maxLevel = c.maxLevel, .threads = 1});
        const int side = 1 << one.level();
        const std::vector<double> reference = referenceMap(env, one.level());
        for (int threads : {1, 2, 3, 7}) {
            SCOPED_TRACE(testing::Message() << threads << " threads");
            const SamplerEnvironment built =
                SamplerEnvironment::build(env, {.maxLevel = c.maxLevel, .threads = threads});
            ASSERT_EQ(built.level(), one.level());
            int differing = 0;
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x)
                    differing += built.cellAverage(built.level(), x, y) !=
                                 reference[size_t(y) * size_t(side) + size_t(x)];
            EXPECT_EQ(differing, 0) << "of " << side * side << " texels";
            EXPECT_EQ(built.effectiveSolidAngle(), one.effectiveSolidAngle());
        }
    }
}

} // namespace
} // namespace wavelit::render
