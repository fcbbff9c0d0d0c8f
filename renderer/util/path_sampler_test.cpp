#include "util/path_sampler.h"

#include "util/chi_square.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace wavelit::util {
namespace {

// The reversed-bits van der Corput and its Sobol' partner (direction numbers v_k = v_{k-1} ^
// v_{k-1} >> 1 from v_0 = 1/2): the first points of the unscrambled sequence.
TEST(PathSampler, SobolMatchesTheFirstPointsOfTheSequence) {
    const double expected[8][2] = {{0, 0},         {0.5, 0.5},     {0.25, 0.75},   {0.75, 0.25},
                                   {0.125, 0.625}, {0.625, 0.125}, {0.375, 0.375}, {0.875, 0.875}};
    for (uint32_t i = 0; i < 8; ++i) {
        const auto [x, y] = sobol2D(i);
        EXPECT_EQ(double(x) * 0x1p-32, expected[i][0]) << i;
        EXPECT_EQ(double(y) * 0x1p-32, expected[i][1]) << i;
    }
}

// The shift-xor form equals the direction-number definition for any 32-bit index.
TEST(PathSampler, SobolEqualsItsDirectionNumberDefinition) {
    auto byDirectionNumbers = [](uint32_t index) {
        uint32_t y = 0, v = 0x80000000U;
        for (uint32_t i = index; i != 0; i >>= 1, v ^= v >> 1)
            if (i & 1U) y ^= v;
        return y;
    };
    uint32_t index = 0;
    for (int k = 0; k < 100000; ++k, index = hashU32(index + 1)) {
        EXPECT_EQ(sobol2D(index).second, byDirectionNumbers(index)) << index;
        EXPECT_EQ(sobol2D(uint32_t(k)).second, byDirectionNumbers(uint32_t(k))) << k;
    }
}

// What the tracer relies on: the first 2^k passes of one pixel put exactly one point of every 2D
// draw into each elementary interval of area 2^-k (a (0, k, 2)-net), whatever the scramble.
TEST(PathSampler, PassesOfOnePixelFormA02NetInEveryDraw) {
    constexpr int kLog = 8, kPasses = 1 << kLog, kGroups = 6;
    for (uint32_t pixel : {0u, 1u, 4095u, 123457u}) {
        std::vector<std::vector<std::pair<float, float>>> points(kGroups);
        for (int pass = 0; pass < kPasses; ++pass) {
            PathSampler s(PathSampler::seedKey(7), pixel, uint32_t(pass));
            for (int g = 0; g < kGroups; ++g) points[g].push_back(s.next2D());
        }
        for (int g = 0; g < kGroups; ++g)
            for (int a = 0; a <= kLog; ++a) {
                const int nx = 1 << a, ny = 1 << (kLog - a);
                std::set<int> cells;
                for (const auto& [x, y] : points[g]) {
                    ASSERT_GE(x, 0.0f);
                    ASSERT_LT(x, 1.0f);
                    ASSERT_GE(y, 0.0f);
                    ASSERT_LT(y, 1.0f);
                    cells.insert(int(x * float(nx)) * ny + int(y * float(ny)));
                }
                EXPECT_EQ(int(cells.size()), kPasses)
                    << "pixel " << pixel << " group " << g << " intervals " << nx << "x" << ny;
            }
    }
}

// Each point alone is uniform (the estimator is unbiased pass by pass): the same pass and draw
// across many pixels, chi-square on a 16 x 16 grid; and across seeds for one pixel.
TEST(PathSampler, OnePointAcrossPixelsAndSeedsIsUniform) {
    constexpr int kCells = 16, kCount = 1 << 16;
    for (uint32_t pass : {0u, 3u, 1000u})
        for (int group : {0, 5}) {
            std::vector<double> observed(kCells * kCells, 0.0),
                expected(kCells * kCells, double(kCount) / (kCells * kCells));
            for (uint32_t i = 0; i < kCount; ++i) {
                const bool acrossSeeds = group == 5;
                PathSampler s(PathSampler::seedKey(acrossSeeds ? i : 11u), acrossSeeds ? 17u : i,
                              pass);
                for (int g = 0; g < group; ++g) s.next2D();
                const auto [x, y] = s.next2D();
                observed[size_t(int(x * kCells) * kCells + int(y * kCells))] += 1.0;
            }
            const ChiSquareResult r = chiSquareTest(observed, expected);
            EXPECT_GT(r.pValue, sidakAlpha(0.01, 6)) << "pass " << pass << " group " << group;
        }
}

// Padding: two draws of one path are not coupled by their stratification. Over the passes of
// one pixel, the correlation of group 0's x with group 1's x (and with the y of the same group)
// is that of independent uniforms, |r| < 4 / sqrt(n).
TEST(PathSampler, DrawsOfOnePathAreDecorrelated) {
    constexpr int kPasses = 4096;
    double sxy = 0, sxz = 0, sx = 0, sy = 0, sz = 0, sxx = 0, syy = 0, szz = 0;
    for (int pass = 0; pass < kPasses; ++pass) {
        PathSampler s(PathSampler::seedKey(3), 99u, uint32_t(pass));
        const auto [x, z] = s.next2D();
        const float y = s.next1D();
        sx += x, sy += y, sz += z, sxy += x * y, sxz += x * z, sxx += x * x, syy += y * y,
            szz += z * z;
    }
    const double n = kPasses;
    auto corr = [n](double sab, double sa, double sb, double saa, double sbb) {
        return (sab / n - sa / n * sb / n) /
               std::sqrt((saa / n - sa * sa / n / n) * (sbb / n - sb * sb / n / n));
    };
    EXPECT_LT(std::abs(corr(sxy, sx, sy, sxx, syy)), 4.0 / std::sqrt(n));
    // Within a group the two coordinates of a (0,2)-sequence are uncorrelated too.
    EXPECT_LT(std::abs(corr(sxz, sx, sz, sxx, szz)), 4.0 / std::sqrt(n));
}

TEST(PathSampler, SeedsAndPixelsGiveDifferentStreams) {
    PathSampler a(PathSampler::seedKey(1), 5, 0), b(PathSampler::seedKey(2), 5, 0),
        c(PathSampler::seedKey(1), 6, 0);
    const float va = a.next1D(), vb = b.next1D(), vc = c.next1D();
    EXPECT_NE(va, vb);
    EXPECT_NE(va, vc);
    // The high word of a 64-bit seed matters.
    EXPECT_NE(PathSampler::seedKey(1), PathSampler::seedKey(1 | (uint64_t(1) << 40)));
}

} // namespace
} // namespace wavelit::util
