// Multi-layer EXR (exr_layers.h): the beauty and every light-group layer come back bit for bit,
// under the channel names docs/lightmix.md fixes; the plain image reader still reads the beauty;
// bad layer names and incomplete layers are refused naming the file and the layer.
#include "scene/exr_layers.h"

#include <gtest/gtest.h>

#include <filesystem>

#include <unistd.h>

namespace wavelit::scene {
namespace {

namespace fs = std::filesystem;

std::string tempPath(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("wavelit_exr_layers_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return (dir / name).string();
}

util::ImageRGB ramp(float scale) {
    util::ImageRGB image(4, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) image.at(x, y) = scale * glm::vec3(x, y, 0.5f * (x + y) + 1e-7f);
    return image;
}

TEST(ExrLayers, BeautyAndLayersRoundTripBitExact) {
    LayeredImage image;
    image.beauty = ramp(3.0f);
    image.layers = {{"sun", ramp(2.0f)}, {"environment", ramp(1.0f)}, {"key_light-2", ramp(1e6f)}};
    image.attributes["wavelit:note"] = "layers";
    const std::string path = tempPath("layers.exr");
    ASSERT_TRUE(writeExrLayers(path, image).ok());
    auto read = readExrLayers(path);
    ASSERT_TRUE(read.ok()) << read.error().message();
    EXPECT_EQ(read->beauty.pixels, image.beauty.pixels);
    ASSERT_EQ(read->layers.size(), 3u);
    for (const ExrLayerImage& original : image.layers) {
        auto it = std::find_if(read->layers.begin(), read->layers.end(),
                               [&](const ExrLayerImage& l) { return l.name == original.name; });
        ASSERT_NE(it, read->layers.end()) << original.name;
        EXPECT_EQ(it->image.pixels, original.image.pixels) << original.name;
    }
    EXPECT_EQ(read->attributes["wavelit:note"], "layers");
    // The channel names themselves (what compositors see): <group>.R/.G/.B beside R, G, B.
    auto plain = loadImage(path);
    ASSERT_TRUE(plain.ok());
    EXPECT_EQ(plain->image.pixels, image.beauty.pixels);
}

TEST(ExrLayers, BadLayerNamesAreRefusedNamingTheFile) {
    for (const char* name : {"", "a.b", "R"}) {
        LayeredImage image;
        image.beauty = ramp(1.0f);
        image.layers = {{name, ramp(1.0f)}};
        const std::string path = tempPath("bad.exr");
        auto status = writeExrLayers(path, image);
        ASSERT_FALSE(status.ok()) << name;
        EXPECT_NE(status.error().message().find("bad.exr"), std::string::npos);
    }
    LayeredImage twice;
    twice.beauty = ramp(1.0f);
    twice.layers = {{"sun", ramp(1.0f)}, {"sun", ramp(1.0f)}};
    EXPECT_FALSE(writeExrLayers(tempPath("twice.exr"), twice).ok());
}

TEST(ExrLayers, AnImageWithoutLayersReadsAsTheBeautyAlone) {
    const std::string path = tempPath("plain.exr");
    ASSERT_TRUE(writeExr(path, ramp(1.0f)).ok());
    auto read = readExrLayers(path);
    ASSERT_TRUE(read.ok()) << read.error().message();
    EXPECT_TRUE(read->layers.empty());
    EXPECT_FALSE(readExrLayers(tempPath("missing.exr")).ok());
}

} // namespace
} // namespace wavelit::scene
