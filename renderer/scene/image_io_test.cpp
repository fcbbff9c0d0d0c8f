#include "scene/image_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace wavelit::scene {
namespace {

namespace fs = std::filesystem;

fs::path tempDir() {
    fs::path dir = fs::temp_directory_path() / ("wavelit_image_io_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

TEST(ImageIo, ExrRoundTripIsBitExactIncludingHugeValues) {
    util::ImageRGB image(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) image.at(x, y) = glm::vec3(x, y, 0.25f * (x + y));
    image.at(2, 1) = glm::vec3(1.0e6f, 3.0e7f, 1e-8f); // an HDR sun beyond half-float range
    const std::string path = (tempDir() / "round_trip.exr").string();
    ASSERT_TRUE(writeExr(path, image).ok());
    auto loaded = loadImage(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message();
    ASSERT_EQ(loaded->image.width, 5);
    ASSERT_EQ(loaded->image.height, 3);
    for (size_t i = 0; i < image.pixels.size(); ++i) EXPECT_EQ(loaded->image.pixels[i], image.pixels[i]);
    EXPECT_TRUE(loaded->warnings.empty());
}

TEST(ImageIo, NonFiniteAndNegativeTexelsAreSanitisedWithAWarningOrRejected) {
    util::ImageRGB image(2, 2, glm::vec3(1.0f));
    image.at(0, 0).r = std::numeric_limits<float>::quiet_NaN();
    image.at(1, 0).g = std::numeric_limits<float>::infinity();
    image.at(1, 1).b = -2.0f;
    const std::string path = (tempDir() / "bad_texels.exr").string();
    ASSERT_TRUE(writeExr(path, image).ok());

    auto fixed = loadImage(path);
    ASSERT_TRUE(fixed.ok());
    EXPECT_EQ(fixed->image.at(0, 0).r, 0.0f);
    EXPECT_EQ(fixed->image.at(1, 0).g, 0.0f);
    EXPECT_EQ(fixed->image.at(1, 1).b, 0.0f);
    ASSERT_EQ(fixed->warnings.size(), 2u);
    EXPECT_NE(fixed->warnings[0].find("bad_texels.exr"), std::string::npos);

    ImageLoadOptions strict;
    strict.sanitize = false;
    auto rejected = loadImage(path, strict);
    ASSERT_FALSE(rejected.ok());
    EXPECT_NE(rejected.error().message().find("(0, 0)"), std::string::npos) << rejected.error().message();
}

TEST(ImageIo, MissingTruncatedAndGarbageFilesGiveErrorsNamingTheFile) {
    const fs::path dir = tempDir();
    auto missing = loadImage((dir / "nope.exr").string());
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message().find("nope.exr"), std::string::npos);

    util::ImageRGB image(64, 64, glm::vec3(0.5f));
    const fs::path good = dir / "good.exr";
    ASSERT_TRUE(writeExr(good.string(), image).ok());
    const auto size = fs::file_size(good);
    fs::copy_file(good, dir / "truncated.exr", fs::copy_options::overwrite_existing);
    fs::resize_file(dir / "truncated.exr", size / 2);
    auto truncated = loadImage((dir / "truncated.exr").string());
    ASSERT_FALSE(truncated.ok());
    EXPECT_NE(truncated.error().message().find("truncated.exr"), std::string::npos);

    std::ofstream(dir / "garbage.exr") << "this is not an image";
    auto garbage = loadImage((dir / "garbage.exr").string());
    ASSERT_FALSE(garbage.ok());
    EXPECT_NE(garbage.error().message().find("garbage.exr"), std::string::npos);
}

TEST(ImageIo, PngIsWrittenWithSrgbEncoding) {
    util::ImageRGB image(3, 1);
    image.at(0, 0) = glm::vec3(0.0f);
    image.at(1, 0) = glm::vec3(1.0f);
    image.at(2, 0) = glm::vec3(0.214041f); // sRGB 0.5
    const fs::path path = tempDir() / "tiny.png";
    ASSERT_TRUE(writePng(path.string(), image).ok());
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    ASSERT_GT(bytes.size(), 8u + 25u);
    EXPECT_EQ(bytes.substr(1, 3), "PNG");
    EXPECT_EQ(bytes.substr(12, 4), "IHDR");
    EXPECT_FALSE(writeImage((tempDir() / "x.jpg").string(), image).ok());
}

TEST(ImageIo, BundledStudioEnvironmentLoads) {
    auto env = loadImage(std::string(WAVELIT_RESOURCE_DIR) + "/envmaps/studio.exr");
    ASSERT_TRUE(env.ok()) << env.error().message();
    EXPECT_EQ(env->image.width, 2 * env->image.height);
    double sum = 0;
    for (auto& p : env->image.pixels) sum += p.r + p.g + p.b;
    EXPECT_GT(sum, 0.0);
}

} // namespace
} // namespace wavelit::scene
