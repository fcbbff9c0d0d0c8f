// The product cache's layout when the device's buffer cannot hold every entry (product_cache.h):
// the pixels that get one are spread over the whole image (no noise step below a line), the
// buffer stays within the bound, and every product pixel is either given an entry or counted.
#include "render/gpu/product_cache.h"

#include "render/testing/cpu_analytic_scenes.h"
#include "scene/bvh.h"

#include <gtest/gtest.h>

#include <vector>

namespace wavelit::render {
namespace {

TEST(GpuProductCacheLayout, EntriesThatDoNotAllFitAreSpreadOverTheImage) {
    scene::Material glossy;
    glossy.id = 1;
    glossy.brdf = "ggx";
    glossy.roughness = 0.3f;
    const auto scene = makeFurnaceScene(glossy, glm::vec3(1.0f), 48, 24);
    const scene::Bvh bvh = scene::buildBvh(*scene);
    GpuSamplerMaterial product; // a per-hit product: a header and a pyramid per entry
    product.mode = kGpuSamplerProduct;
    const std::vector<GpuSamplerMaterial> materials{product};
    constexpr int kSize = 64;
    const GpuProductCacheLayout all =
        layoutGpuProductCache(*scene, bvh, kSize, kSize, materials, UINT64_MAX);
    ASSERT_GT(all.entries, 1000u); // the sphere fills ~70% of the image height
    EXPECT_EQ(all.skipped, 0u);
    EXPECT_EQ(all.pyramidEntries, all.entries);

    const uint64_t maxBytes = all.bytes() / 3; // room for about a third of the entries
    const GpuProductCacheLayout some =
        layoutGpuProductCache(*scene, bvh, kSize, kSize, materials, maxBytes);
    EXPECT_LE(some.bytes(), maxBytes);
    EXPECT_EQ(some.entries + some.skipped, all.entries);
    EXPECT_GT(some.entries, all.entries / 4);
    // The share of product pixels with an entry, per quarter of the rows, against the whole's.
    const double whole = double(some.entries) / double(all.entries);
    for (int quarter = 0; quarter < 4; ++quarter) {
        uint64_t product = 0, given = 0;
        for (int y = quarter * kSize / 4; y < (quarter + 1) * kSize / 4; ++y)
            for (int x = 0; x < kSize; ++x) {
                const size_t i = size_t(y) * kSize + size_t(x);
                product += all.words[i] != GpuProductCacheLayout::kNoEntry;
                given += some.words[i] != GpuProductCacheLayout::kNoEntry;
            }
        if (product < 100) continue; // the sphere's thin top and bottom
        EXPECT_NEAR(double(given) / double(product), whole, 0.1) << "rows quarter " << quarter;
    }
}

} // namespace
} // namespace wavelit::render
