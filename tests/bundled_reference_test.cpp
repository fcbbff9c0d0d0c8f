// The bundled converged reference (resources/references/README.md) still shows the default scene:
// a fresh 32-spp render on the CPU tracer agrees with it in the mean and block by block. README
// command 1 judges every sampler's error against this image, so a stale one (the scene, its
// lighting setup or its map edited without regenerating it) would silently report wrong errors.
#include "render/session/image_metrics.h"
#include "render/session/render_session.h"
#include "scene/image_io.h"
#include "scene/scene_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

namespace wavelit {
namespace {

namespace fs = std::filesystem;

// Mean channel value of each block x block tile.
std::vector<double> blockMeans(const util::ImageRGB& image, int block) {
    std::vector<double> means;
    for (int by = 0; by + block <= image.height; by += block)
        for (int bx = 0; bx + block <= image.width; bx += block) {
            double sum = 0.0;
            for (int y = by; y < by + block; ++y)
                for (int x = bx; x < bx + block; ++x) {
                    const glm::vec3 p = image.at(x, y);
                    sum += (double(p.r) + p.g + p.b) / 3.0;
                }
            means.push_back(sum / double(block * block));
        }
    return means;
}

TEST(BundledReference, MatchesAFreshRenderOfTheDefaultScene) {
    const fs::path resources(WAVELIT_RESOURCE_DIR);
    const fs::path referencePath = resources / "references/ring_on_ground_128.exr";
    const fs::path scenePath = resources / "scenes/ring_on_ground.wlscene";
    if (!fs::exists(scenePath))
        GTEST_SKIP() << "default scene not present";
    ASSERT_TRUE(fs::exists(referencePath)) << referencePath << ": scripts/run.sh measures against it";
    auto reference = scene::loadImage(referencePath.string());
    ASSERT_TRUE(reference.ok()) << reference.error().message();
    ASSERT_EQ(reference->image.width, 128);
    ASSERT_EQ(reference->image.height, 128);
    EXPECT_EQ(render::countNonFinite(reference->image), 0u);

    auto scene = scene::loadScene(scenePath.string());
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    render::RenderOptions options;
    options.width = 128;
    options.height = 128;
    options.bounces = scene->render.bounces;
    options.device = render::DeviceChoice::Cpu;
    options.sampler = render::SamplerKind::Mis;
    options.seed = 31337; // not the reference's
    auto session = render::RenderSession::create(*scene, options);
    ASSERT_TRUE(session.ok()) << session.error().message();
    for (int pass = 0; pass < 32; ++pass)
        ASSERT_TRUE((*session)->renderPass().ok());
    auto fresh = (*session)->image();
    ASSERT_TRUE(fresh.ok());

    const double refMean = render::meanValue(reference->image), freshMean = render::meanValue(*fresh);
    EXPECT_NEAR(freshMean / refMean, 1.0, 0.03) << "means " << freshMean << " vs " << refMean;
    // 16 x 16 blocks (64 of them), each 8192 samples here: a block's relative noise is a few
    // per cent; the median of |relative difference| is robust to the sun's fireflies.
    const std::vector<double> a = blockMeans(*fresh, 16), b = blockMeans(reference->image, 16);
    std::vector<double> relative;
    for (size_t i = 0; i < a.size(); ++i)
        relative.push_back(std::abs(a[i] - b[i]) / std::max(b[i], 1e-3));
    std::nth_element(relative.begin(), relative.begin() + long(relative.size() / 2), relative.end());
    const double median = relative[relative.size() / 2];
    std::printf("bundled reference: means %.5f (fresh, 32 spp) vs %.5f; median block |rel diff| %.4f\n",
                freshMean, refMean, median);
    EXPECT_LT(median, 0.05);
}

} // namespace
} // namespace wavelit
