// What the SamplerTablesCache tests share (sampler_tables_cache_test.cpp, its environment edits in
// sampler_tables_cache_environment_test.cpp): a two-material test scene, the rebuild counters'
// expectations, and the comparison of tables with a fresh build. Test-only (GoogleTest).
#pragma once

#include "render/sampling/sampler_tables_cache.h"

#include <gtest/gtest.h>

#include <regex>
#include <string>

namespace wavelit::render::sampler_tables_test {

// Indices of the test scene's materials (and the default one, unused) in Scene::materials order.
inline constexpr size_t kGgx = 0, kLambert = 1, kDefault = 2;

// Two spheres: a GGX one (roughness 0.35, where the product policy builds windowed bins: its lobe
// is 4.4 env texels wide, over the 4 below which the policy takes mis's technique) and a
// Lambert one, under a 64 x 32 sky with a sun (env level 6: a small but lit map).
scene::Scene testScene(); // defined in sampler_tables_cache_test.cpp (it uses render/testing/)

struct Counts {
    int envBuilds, materialBuilds, envReuses, materialReuses;
};

inline void expectCounts(const SamplerTablesRebuilds& r, Counts c) {
    EXPECT_EQ(r.environmentBuilds, c.envBuilds);
    EXPECT_EQ(r.materialBuilds, c.materialBuilds);
    EXPECT_EQ(r.environmentReuses, c.envReuses);
    EXPECT_EQ(r.materialReuses, c.materialReuses);
}

// Product tables of scene material `m`: nullptr when it has none.
inline const MaterialProductTables* product(const SceneSamplerTables& t, size_t m) {
    const int i = t.samplerIndexOfMaterial.at(m);
    return i < 0 ? nullptr : t.tables->productTables(size_t(i));
}

// The report with build times and reuse marks removed: what a fresh build must reproduce.
inline std::string reportWithoutTimings(const DirectionSamplerTables& t) {
    static const std::regex timing(R"(built in [0-9.]+ ms| \(reused\)| \(the previous, turned\))");
    return std::regex_replace(t.report(), timing, "");
}

// Same content as a fresh build of the same scene: report text, env tables, and every product
// table's flat export (the arrays the GPU reads) word for word.
inline void expectSameAsFreshBuild(const scene::Scene& scene, const SceneSamplerTables& got) {
    SamplerTablesCache fresh;
    auto want = fresh.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(want.ok());
    EXPECT_EQ(got.samplerIndexOfMaterial, want->samplerIndexOfMaterial);
    const DirectionSamplerTables &a = *got.tables, &b = *want->tables;
    EXPECT_EQ(reportWithoutTimings(a), reportWithoutTimings(b));
    EXPECT_EQ(a.environment().level(), b.environment().level());
    EXPECT_EQ(a.environment().bytes(), b.environment().bytes());
    const int side = 1 << a.environment().level();
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            ASSERT_EQ(a.environment().cellAverage(a.environment().level(), x, y),
                      b.environment().cellAverage(b.environment().level(), x, y));
    EXPECT_EQ(a.environment().effectiveSolidAngle(), b.environment().effectiveSolidAngle());
    EXPECT_TRUE(a.environment().exact().pdfTable() == b.environment().exact().pdfTable());
    EXPECT_TRUE(a.environment().exact().columnCdf() == b.environment().exact().columnCdf());
    EXPECT_TRUE(a.environment().exact().rowCdf() == b.environment().exact().rowCdf());
    ASSERT_EQ(a.materialCount(), b.materialCount());
    for (size_t i = 0; i < a.materialCount(); ++i) {
        ASSERT_TRUE(a.productTables(i) && b.productTables(i));
        const FlatProductTables fa = a.productTables(i)->flatten(),
                                fb = b.productTables(i)->flatten();
        EXPECT_EQ(fa.header, fb.header) << a.material(i).name;
        EXPECT_EQ(fa.nodeWords, fb.nodeWords) << a.material(i).name;
        EXPECT_EQ(fa.scaling, fb.scaling) << a.material(i).name;
    }
}

} // namespace wavelit::render::sampler_tables_test
