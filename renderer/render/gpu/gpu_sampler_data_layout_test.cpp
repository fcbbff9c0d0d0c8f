// The exact env technique's tables in samplerWords (gpu_sampler_data.h): every double on an 8-byte
// boundary, so env_exact.glsl can read it through the buffer's u64 view, and each table where
// GpuEnvExactLayout (and the shader's same arithmetic) says, holding the CPU sampler's values.
// A 7 x 5 map: odd height and odd texel count, so both guides need their padding word. The flat
// product tables likewise: each material's header at an odd word, so its bin and factor word pairs
// and its nodes' (detail 2, detail 3) and child pairs are on 8-byte boundaries for the u64 reads of
// env_product_tables.glsl, holding flatten()'s words.
#include "render/gpu/gpu_sampler_data.h"

#include "plugins/brdf_table.h"
#include "render/sampling/product/flat_product_layout.h"
#include "render/sampling/direction_sampler_tables.h"
#include "render/sampling/sampler_constants.h"
#include "render/sampling/sampler_tables_cache.h"
#include "render/testing/sampler_test_envs.h"
#include "util/image.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <memory>
#include <string>
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

TEST(GpuSamplerData, FlatProductTablesAreEightByteAlignedWhereTheShaderReadsPairs) {
    namespace fl = flat_layout;
    // 256 x 128 with a 13-degree sun (~0.05 sr, 10^4 x the sky) of the glossy lobes' extent:
    // every material gets a per-hit product (the two-sided extents rule), windowed for the r = 0.2
    // lobes, whole-sphere about the normal for the measured table. (A one-texel source sits
    // inside every lobe the product resolves: those take mis's technique.)
    auto copper = plugins::loadMerlBrdf(std::string(WAVELIT_RESOURCE_DIR) +
                                        "/brdfs/glossy-copper-r05.binary");
    ASSERT_TRUE(copper.ok()) << copper.error().message();
    const scene::Environment env =
        makeSunSkyEnvironment(256, glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f)), 1e4, 13.0);
    const std::vector<SamplerMaterial> materials = {
        {"ggx r=0.2", plugins::findBrdf("ggx"), {glm::vec3(0.9f), 0.2f}},
        {"measured", plugins::findBrdf("measured"), {glm::vec3(1.0f), 0.5f, 0.0f, *copper}},
        {"blinn r=0.2", plugins::findBrdf("blinn"), {glm::vec3(0.9f), 0.2f}},
    };
    SceneSamplerTables scene;
    scene.samplerIndexOfMaterial = {0, 1, 2};
    scene.tables = DirectionSamplerTables::build(env, materials, SamplerKind::Wavelet);
    auto packed = packGpuSamplers(scene, SamplerKind::Wavelet, materials.size());
    ASSERT_TRUE(packed.ok()) << packed.error().message();
    const std::vector<uint32_t>& w = packed->words;
    EXPECT_EQ(w.size() % 2, 0u);
    for (size_t i = 0; i < materials.size(); ++i) {
        SCOPED_TRACE(materials[i].name);
        const GpuSamplerMaterial& g = packed->materials[i];
        ASSERT_EQ(g.mode, kGpuSamplerProduct);
        const FlatProductTables flat = scene.tables->productTables(i)->flatten();
        EXPECT_EQ(g.tableOffset % 2, 1u);
        expectWords(w, g.tableOffset, flat.header);
        const uint32_t bins = w[g.tableOffset + fl::kBinCount];
        const uint32_t factors = w[g.tableOffset + fl::kFactorCount];
        ASSERT_GT(bins, 0u);
        ASSERT_GT(factors, 0u);
        // The shader's pair reads: (k, ox), (oy, factor) per bin and (firstNode, nodeCount).
        for (uint32_t b = 0; b < bins; ++b) {
            const uint32_t at = g.tableOffset + uint32_t(fl::binWordsAt(int(b)));
            EXPECT_EQ((at + fl::kBinK) % 2, 0u);
            EXPECT_EQ((at + fl::kBinOy) % 2, 0u);
        }
        for (uint32_t f = 0; f < factors; ++f)
            EXPECT_EQ((g.tableOffset + uint32_t(fl::factorWordsAt(int(bins), int(f))) +
                       fl::kFactorFirstNode) % 2, 0u);
        EXPECT_EQ(g.nodeOffset % 2, 0u);
        ASSERT_FALSE(flat.nodeWords.empty());
        expectWords(w, g.nodeOffset, flat.nodeWords);
        for (uint32_t n = 0; n < flat.nodeWords.size() / fl::kNodeWords; ++n) {
            const uint32_t base = g.nodeOffset + n * fl::kNodeWords;
            EXPECT_EQ((base + fl::kNodeDetail + 1) % 2, 0u);
            EXPECT_EQ((base + fl::kNodeChild) % 2, 0u);
            EXPECT_EQ((base + fl::kNodeChild + 2) % 2, 0u);
        }
        for (size_t f = 0; f < flat.scaling.size(); ++f)
            ASSERT_EQ(std::bit_cast<float>(w[g.scalingOffset + f]), flat.scaling[f]);
    }
}

} // namespace
} // namespace wavelit::render
