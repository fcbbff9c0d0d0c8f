// The exact env technique's tables in samplerWords (gpu_sampler_data.h): every double on an 8-byte
// boundary, so env_exact.glsl can read it through the buffer's u64 view, and each table where
// GpuEnvExactLayout (and the shader's same arithmetic) says, holding the CPU sampler's values.
// A 7 x 5 map: odd height and odd texel count, so both guides need their padding word. (The
// precomputed pyramids' alignment has no test: since round 5 of the EnvMis policy no material
// reaches them; docs/performance.md "Equal time, round 5".)
#include "render/gpu/gpu_sampler_data.h"

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

} // namespace
} // namespace wavelit::render
