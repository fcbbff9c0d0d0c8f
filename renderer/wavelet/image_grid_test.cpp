#include "wavelet/image_grid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wavelit::wavelet {
namespace {

TEST(ImageGrid, ChannelsAndLuminanceKeepTheRowOrder) {
    util::ImageRGB img(4, 4, glm::vec3(1.0f, 2.0f, 3.0f));
    img.at(1, 0) = glm::vec3(10.0f, 0.0f, 0.0f); // top row, second column
    auto r = channelGrid(img, 0, "a.exr");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->level, 2);
    EXPECT_EQ(r->at(1, 0), 10.0);
    EXPECT_EQ(r->at(0, 3), 1.0);
    auto y = luminanceGrid(img);
    ASSERT_TRUE(y.ok());
    EXPECT_DOUBLE_EQ(y->at(0, 0), 0.2126 * 1.0 + 0.7152 * 2.0 + 0.0722 * 3.0);
}

TEST(ImageGrid, BadImagesAreErrorsNamingTheFile) {
    auto wide = channelGrid(util::ImageRGB(8, 4), 1, "wide.exr");
    ASSERT_FALSE(wide.ok());
    EXPECT_EQ(wide.error().file, "wide.exr");
    EXPECT_NE(wide.error().reason.find("not square"), std::string::npos);
    EXPECT_FALSE(luminanceGrid(util::ImageRGB(12, 12), "npot.exr").ok());
    util::ImageRGB inf(4, 4);
    inf.at(2, 1).b = INFINITY;
    auto bad = luminanceGrid(inf, "inf.exr");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message().find("texel (2, 1)"), std::string::npos);
}

} // namespace
} // namespace wavelit::wavelet
