// The exact env technique's tables in samplerWords (gpu_sampler_data.h): every double on an 8-byte
// boundary, so env_exact.glsl can read it through the buffer's u64 view, and each table where
// GpuEnvExactLayout (and the shader's same arithmetic) says, holding the CPU sampler's values.
// A 7 x 5 map: odd height and odd texel count, so both guides need their padding word. And a
// Lambert lobe's precomputed pyramids: from an odd word, at an even stride, so sibling cells pair
// up on 8-byte boundaries (precomputed_products.h precomputedBinWords).
#include "render/gpu/gpu_sampler_data.h"

#include "render/gpu/precomputed_products.h"
#include "plugins/brdf_table.h"
#include "render/sampling/direction_sampler_tables.h"
#include "render/sampling/sampler_constants.h"
#include "render/sampling/sampler_tables_cache.h"
#include "util/image.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <memory>
#include <vector>

namespace wavelit::render {
namespace {

double doubleAt(const std::vector<uint32_t>& w, uint32_t i) {
    return std::bit_cast<double>(uint64_t(w[i]) | (uint64_t(w[i + 1]) << 32));
}

void expectDoubles(const std::vector<uint32_t>& w, uint32_t at, const std::vector<double>& v) {
    ASSERT_EQ(at % 2, 0u);
    for (size_t i = 0; i < v.size(); ++i)
        ASSERT_EQ(doubleAt(w, at + 2 * uint32_t(i)), v[i]) << "entry " << i;
}

void expectWords(const std::vector<uint32_t>& w, uint32_t at, const std::vector<uint32_t>& v) {
    for (size_t i = 0; i < v.size(); ++i)
        ASSERT_EQ(w[at + i], v[i]) << "entry " << i;
}

TEST(GpuSamplerData, ExactEnvTablesAreEightByteAlignedWhereTheLayoutSays) {
    auto image = std::make_shared<util::ImageRGB>(7, 5, glm::vec3(0.5f));
    image->at(3, 1) = glm::vec3(40.0f);
    scene::Environment env;
    env.image = image;
    for (SamplerKind kind : {SamplerKind::Mis, SamplerKind::Wavelet}) {
        SceneSamplerTables scene;
        scene.samplerIndexOfMaterial = {0};
        scene.tables = DirectionSamplerTables::build(
            env, {{"lambert", plugins::findBrdf("lambert"), {glm::vec3(0.8f), 1.0f}}}, kind);
        auto packed = packGpuSamplers(scene, kind, 1);
        ASSERT_TRUE(packed.ok()) << packed.error().message();
        const std::vector<uint32_t>& w = packed->words;
        EXPECT_EQ(w.size() % 2, 0u);
        EXPECT_EQ(packed->tailOffset % 2, 0u);
        const uint32_t offset = packed->tailOffset + (1u << (2 * kTailLevel));
        const EquirectEnvSampler& exact = scene.tables->environment().exact();
        ASSERT_EQ(w[offset], uint32_t(exact.width()));
        ASSERT_EQ(w[offset + 1], uint32_t(exact.height()));
        const GpuEnvExactLayout l = gpuEnvExactLayout(offset, w[offset], w[offset + 1]);
        for (uint32_t at : {l.rowSolidAngle, l.rowCdf, l.rowGuide, l.columnCdf, l.columnGuide, l.pdfs})
            EXPECT_EQ(at % 2, 0u);
        EXPECT_LE(l.end, w.size());
        expectDoubles(w, l.rowSolidAngle, exact.rowSolidAngle());
        expectDoubles(w, l.rowCdf, exact.rowCdf());
        expectWords(w, l.rowGuide, exact.rowGuide());
        expectDoubles(w, l.columnCdf, exact.columnCdf());
        expectWords(w, l.columnGuide, exact.columnGuide());
        expectDoubles(w, l.pdfs, exact.pdfTable());
    }
}

TEST(GpuSamplerData, PrecomputedPyramidSiblingsAreEightByteAligned) {
    // A bright upper half: the cosine lobe keeps its product (gpu_sampler_data_test.cpp).
    auto image = std::make_shared<util::ImageRGB>(64, 32, glm::vec3(0.5f));
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 64; ++x)
            image->at(x, y) = glm::vec3(1.0f);
    scene::Environment env;
    env.image = image;
    SceneSamplerTables scene;
    scene.samplerIndexOfMaterial = {0};
    scene.tables = DirectionSamplerTables::build(
        env, {{"lambert", plugins::findBrdf("lambert"), {glm::vec3(0.8f), 1.0f}}},
        SamplerKind::Wavelet);
    auto packed = packGpuSamplers(scene, SamplerKind::Wavelet, 1);
    ASSERT_TRUE(packed.ok()) << packed.error().message();
    const GpuSamplerMaterial& g = packed->materials[0];
    ASSERT_GT(g.precomputedBins, 0u);
    EXPECT_EQ(g.precomputedOffset % 2, 1u);
    const int m =
        std::min(scene.tables->productTables(0)->policy().productLevel, kGpuMaxProductLevel);
    const uint32_t stride = uint32_t(precomputedBinWords(m));
    EXPECT_EQ(stride % 2, 0u);
    EXPECT_GE(stride, uint32_t(kPrecomputedBinHeaderWords + precomputedPyramidFloats(m)));
    // The bins end where the tail starts, up to the one word that makes tailOffset even.
    const uint32_t end = g.precomputedOffset + g.precomputedBins * g.precomputedBins * stride;
    EXPECT_TRUE(end == packed->tailOffset || end + 1 == packed->tailOffset) << end;
    // Level l >= 1 starts at (4^l - 1) / 3, odd: pairs (even cell index + odd base) are even.
    const uint32_t massOffset = g.precomputedOffset + kPrecomputedBinHeaderWords;
    for (int l = 1; l <= m; ++l)
        EXPECT_EQ((massOffset + uint32_t((1 << (2 * l)) - 1) / 3) % 2, 0u) << "level " << l;
}

} // namespace
} // namespace wavelit::render
