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
                product += all.offsets[i] != GpuProductCacheLayout::kNoEntry;
                given += some.offsets[i] != GpuProductCacheLayout::kNoEntry;
            }
        if (product < 100) continue; // the sphere's thin top and bottom
        EXPECT_NEAR(double(given) / double(product), whole, 0.1) << "rows quarter " << quarter;
    }
}

// product_cache.glsl reads and writes the entries through the buffer's u64 view: at an odd
// pixel count (an odd number of offset words) every entry still starts on an 8-byte boundary,
// entries of either kind (header only, header + pyramid) have even sizes, a pyramid starts at
// an odd word (its sibling cells of levels >= 1 pair up in u64s), and the buffer is whole u64s.
TEST(GpuProductCacheLayout, EntriesAndPyramidsSitWhereTheU64ReadsNeedThem) {
    scene::Material glossy;
    glossy.id = 1;
    glossy.brdf = "ggx";
    glossy.roughness = 0.3f;
    const auto scene = makeFurnaceScene(glossy, glm::vec3(1.0f), 48, 24);
    const scene::Bvh bvh = scene::buildBvh(*scene);
    EXPECT_EQ(GpuProductCacheLayout::kPyramidAt % 2, 1u);
    for (uint32_t mode : {kGpuSamplerProduct, kGpuSamplerBsdfLobe}) {
        SCOPED_TRACE(mode);
        GpuSamplerMaterial material;
        material.mode = mode;
        const std::vector<GpuSamplerMaterial> materials{material};
        constexpr int kWidth = 33, kHeight = 31; // 1023 pixels: an odd count of offset words
        const GpuProductCacheLayout layout =
            layoutGpuProductCache(*scene, bvh, kWidth, kHeight, materials, UINT64_MAX);
        ASSERT_GT(layout.entries, 100u);
        EXPECT_EQ(layout.offsets.size() % 2, 0u);
        EXPECT_EQ(layout.words % 2, 0u);
        const uint32_t entryWords = mode == kGpuSamplerProduct
                                        ? gpuProductCachePyramidEntryWords()
                                        : GpuProductCacheLayout::kHeaderWords;
        EXPECT_EQ(entryWords % 2, 0u);
        EXPECT_EQ(layout.pyramidEntries, mode == kGpuSamplerProduct ? layout.entries : 0u);
        uint32_t expected = kWidth * kHeight + 1; // the first entry, after the pad word
        for (int i = 0; i < kWidth * kHeight; ++i) {
            const uint32_t at = layout.offsets[size_t(i)];
            if (at == GpuProductCacheLayout::kNoEntry) continue;
            ASSERT_EQ(at, expected) << "pixel " << i; // in pixel order, back to back
            ASSERT_EQ(at % 2, 0u) << "pixel " << i;
            expected += entryWords;
        }
        EXPECT_EQ(uint64_t(expected), layout.words);
        // Each level l >= 1 of a pyramid (at its entry's kPyramidAt) starts at an even word, and
        // a row of its cells has an even count: cells (2x, 2x + 1) share a u64.
        for (int l = 1; l <= kGpuMaxProductLevel; ++l)
            EXPECT_EQ((GpuProductCacheLayout::kPyramidAt + ((1u << (2 * l)) - 1u) / 3u) % 2, 0u)
                << "level " << l;
    }
}

} // namespace
} // namespace wavelit::render
