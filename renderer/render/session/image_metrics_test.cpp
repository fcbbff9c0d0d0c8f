#include "render/session/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace wavelit::render {
namespace {

TEST(ImageMetrics, RmseOfAConstantOffsetIsTheOffset) {
    util::ImageRGB a(4, 3, glm::vec3(1.0f)), b(4, 3, glm::vec3(1.5f));
    EXPECT_DOUBLE_EQ(rmse(a, b), 0.5);
    EXPECT_DOUBLE_EQ(rmse(a, a), 0.0);
    // One channel of one pixel off by 6: sqrt(36 / 36 values) = 1.
    util::ImageRGB c = a;
    c.at(2, 1).g += 6.0f;
    EXPECT_DOUBLE_EQ(rmse(c, a), 1.0);
    EXPECT_NEAR(relativeMse(b, a), 0.25 / 1.01, 1e-12);
}

TEST(ImageMetrics, CountsNonFiniteValuesAndMeans) {
    util::ImageRGB a(2, 2, glm::vec3(2.0f));
    EXPECT_EQ(countNonFinite(a), 0u);
    EXPECT_DOUBLE_EQ(meanValue(a), 2.0);
    a.at(0, 0).r = std::numeric_limits<float>::quiet_NaN();
    a.at(1, 1).b = std::numeric_limits<float>::infinity();
    EXPECT_EQ(countNonFinite(a), 2u);
}

} // namespace
} // namespace wavelit::render
