// architecture.md §8 "cached products against full recomputation": after every kind of edit the
// incremental preview equals a preview built from scratch on the edited scene (≤ 1e-6 relative;
// per point the same inputs go through the same code, so in practice bit for bit).
#include "relight/relight_preview.h"
#include "relight/relight_test_support.h"
#include "relight/colour_use.h"
#include "relight/sphere_level.h"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

namespace wavelit::relight {
namespace {

struct EditCase {
    const char* name;
    scene::EntityKind kind;
    scene::EntityId id;
    const char* property;
    scene::PropertyValue value;
    const char* expectedKind;
};

void PrintTo(const EditCase& e, std::ostream* os) { *os << e.name; }

void expectSameImage(const util::ImageRGB& a, const util::ImageRGB& b) {
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double x = a.pixels[i][c], y = b.pixels[i][c];
            ASSERT_LE(std::abs(x - y), 1e-6 * std::max(std::abs(y), 1e-6)) << "pixel " << i << " channel " << c;
        }
}

class RelightEditTest : public ::testing::TestWithParam<EditCase> {};

TEST_P(RelightEditTest, IncrementalEqualsFromScratch) {
    const EditCase& e = GetParam();
    scene::Scene scene = testing::makeRelightScene();
    auto preview = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(preview);
    const util::ImageRGB before = (*preview)->image();
    scene::ChangeSet changes;
    ASSERT_TRUE(changes.setProperty(scene, {e.kind, e.id}, e.property, e.value));
    ASSERT_TRUE(changes.apply(scene));
    const EditSummary summary = (*preview)->applyChanges(scene, changes);
    EXPECT_EQ(summary.kind, e.expectedKind);
    EXPECT_FALSE(summary.factorsRebuilt.empty());
    auto scratch = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(scratch);
    const util::ImageRGB after = (*preview)->image();
    expectSameImage(after, (*scratch)->image());
    // The edit did something visible (a test of nothing would pass too).
    double change = 0.0;
    for (size_t i = 0; i < after.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) change += std::abs(after.pixels[i][c] - before.pixels[i][c]);
    EXPECT_GT(change, 0.0);
}

using K = scene::EntityKind;
INSTANTIATE_TEST_SUITE_P(
    EveryEditKind, RelightEditTest,
    ::testing::Values(
        EditCase{"EnvRotation", K::Environment, 0, "rotation", 75.0f, "environment"},
        EditCase{"EnvIntensity", K::Environment, 0, "intensity", 2.5f, "environment"},
        EditCase{"EnvTint", K::Environment, 0, "tint", glm::vec3(1.0f, 0.5f, 0.2f), "environment"},
        EditCase{"PointMove", K::Light, 6, "position", glm::vec3(-1.0f, 1.5f, 1.5f), "light"},
        EditCase{"PointIntensity", K::Light, 6, "intensity", 120.0f, "light"},
        EditCase{"RectMove", K::Light, 7, "position", glm::vec3(-0.5f, 1.5f, 0.5f), "light"},
        EditCase{"SphereRadius", K::Light, 8, "radius", 0.2f, "light"},
        EditCase{"SunDirection", K::Light, 9, "direction", glm::vec3(0.4f, -1.0f, 0.1f), "light"},
        EditCase{"MaterialColor", K::Material, 1, "baseColor", glm::vec3(0.2f, 0.7f, 0.3f), "material"},
        EditCase{"MaterialRoughness", K::Material, 2, "roughness", 0.1f, "material"},
        EditCase{"GgxColor", K::Material, 2, "baseColor", glm::vec3(0.1f, 0.9f, 0.4f), "material"},
        EditCase{"MaterialEmission", K::Material, 1, "emission", glm::vec3(0.5f, 0.1f, 0.0f), "material"},
        EditCase{"ObjectMove", K::Object, 4, "translation", glm::vec3(0.6f, 0.5f, 0.3f), "object"},
        EditCase{"ObjectRotate", K::Object, 4, "rotation", glm::vec3(0.0f, 30.0f, 0.0f), "object"},
        EditCase{"ObjectMaterial", K::Object, 4, "material", scene::EntityId(1), "object"},
        EditCase{"Camera", K::Camera, 0, "position", glm::vec3(1.0f, 2.0f, 5.0f), "camera"}),
    [](const ::testing::TestParamInfo<EditCase>& info) { return std::string(info.param.name); });

TEST(RelightPreview, ASequenceOfEditsStaysEqualToFromScratch) {
    scene::Scene scene = testing::makeRelightScene();
    auto preview = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(preview);
    const std::vector<std::tuple<scene::EntityRef, const char*, scene::PropertyValue>> edits = {
        {{K::Object, 4}, "translation", glm::vec3(-0.8f, 0.5f, 0.0f)},
        {{K::Light, 6}, "intensity", 10.0f},
        {{K::Environment, 0}, "rotation", 200.0f},
        {{K::Material, 2}, "baseColor", glm::vec3(0.3f)},
        {{K::Object, 4}, "translation", glm::vec3(0.8f, 0.5f, -0.5f)}};
    for (const auto& [ref, property, value] : edits) {
        scene::ChangeSet changes;
        ASSERT_TRUE(changes.setProperty(scene, ref, property, value));
        ASSERT_TRUE(changes.apply(scene));
        (*preview)->applyChanges(scene, changes);
    }
    auto scratch = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(scratch);
    expectSameImage((*preview)->image(), (*scratch)->image());
}

// A colour or emission edit of a material whose BRDF is linear (lambert) or affine (ggx's Schlick
// F0) in its colour touches no point: the terms are cached for white and black and mixed in the
// image (colour_use.h); the image still equals a build from scratch (EveryEditKind above).
TEST(RelightPreview, ColourEditsOfLinearAndAffineBrdfsTouchNoPoint) {
    scene::Scene scene = testing::makeRelightScene();
    auto preview = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(preview);
    for (const auto& [id, property, value] :
         std::vector<std::tuple<scene::EntityId, const char*, glm::vec3>>{
             {1, "baseColor", glm::vec3(0.1f, 0.2f, 0.9f)}, {2, "baseColor", glm::vec3(0.9f, 0.1f, 0.1f)},
             {2, "emission", glm::vec3(1.0f)}}) {
        scene::ChangeSet changes;
        ASSERT_TRUE(changes.setProperty(scene, {K::Material, id}, property, value));
        ASSERT_TRUE(changes.apply(scene));
        const EditSummary summary = (*preview)->applyChanges(scene, changes);
        EXPECT_EQ(summary.kind, "material");
        EXPECT_EQ(summary.pointsTouched, 0u) << property << " of material " << id;
    }
    // A roughness edit still rebuilds T on the material's points.
    scene::ChangeSet changes;
    ASSERT_TRUE(changes.setProperty(scene, {K::Material, 2}, "roughness", 0.6f));
    ASSERT_TRUE(changes.apply(scene));
    EXPECT_GT((*preview)->applyChanges(scene, changes).pointsTouched, 0u);
}

// Lambert with its f recoloured by `shape` (f = shape(params, lambert's f, lambert's f at a white
// colour)): BRDFs the colour-use probe must classify, everything but eval forwarded to lambert.
class ReColouredLambert final : public plugins::Brdf {
public:
    using Shape = glm::vec3 (*)(const plugins::BrdfParams&, const glm::vec3& f, const glm::vec3& fWhite);
    ReColouredLambert(const char* name, Shape shape) : m_name(name), m_shape(shape) {}
    const char* name() const override { return m_name; }
    std::span<const plugins::BrdfParameterInfo> parameters() const override { return m_base.parameters(); }
    plugins::BrdfLobeAxis lobeAxis() const override { return m_base.lobeAxis(); }
    plugins::BrdfLobeWidth lobeWidth(const plugins::BrdfParams& p) const override { return m_base.lobeWidth(p); }
    plugins::BrdfGpuTwin gpuTwin() const override { return {}; }
    glm::vec3 eval(const plugins::BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        return m_shape(p, m_base.eval(p, wo, wi), m_base.eval(plugins::BrdfParams(glm::vec3(1.0f), 1.0f), wo, wi));
    }
    plugins::BrdfSample sample(const plugins::BrdfParams& p, const glm::vec3& wo, float u1, float u2) const override {
        return m_base.sample(p, wo, u1, u2);
    }
    float pdf(const plugins::BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        return m_base.pdf(p, wo, wi);
    }
    std::optional<glm::vec2> invert(const plugins::BrdfParams& p, const glm::vec3& wo,
                                    const glm::vec3& wi) const override {
        return m_base.invert(p, wo, wi);
    }

private:
    const plugins::Brdf& m_base = *plugins::findBrdf("lambert");
    const char* m_name;
    Shape m_shape;
};

// f(c) against direct evaluation: the class the probe finds for each plugin, and a plugin that is
// not affine in its colour (f = c^2 / pi) is Fixed, so its colour edits rebuild T.
TEST(RelightColourUse, ClassifiesThePluginsAndRefusesANonAffineOne) {
    plugins::BrdfParams params(glm::vec3(0.5f), 0.3f);
    EXPECT_EQ(colourUseOf(*plugins::findBrdf("lambert"), params), ColourUse::Linear);
    EXPECT_EQ(colourUseOf(*plugins::findBrdf("ggx"), params), ColourUse::Affine);
    const ReColouredLambert squared("squared", [](const plugins::BrdfParams& p, const glm::vec3& f, const glm::vec3&) {
        return p.baseColor * f;
    });
    EXPECT_EQ(colourUseOf(squared, params), ColourUse::Fixed);
    // Every registered plugin's class reproduces f at a colour it was not probed with.
    const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, -0.2f, 0.8f)), wi = glm::normalize(glm::vec3(-0.25f, 0.3f, 0.7f));
    for (const plugins::Brdf* brdf : plugins::brdfRegistry()) {
        if (plugins::brdfReadsFile(*brdf)) continue; // needs a table
        const ColourUse use = colourUseOf(*brdf, params);
        plugins::BrdfParams c = params, black = params, white = params;
        c.baseColor = glm::vec3(0.33f, 0.61f, 0.12f);
        black.baseColor = glm::vec3(0.0f);
        white.baseColor = glm::vec3(1.0f);
        const glm::vec3 direct = brdf->eval(c, wo, wi), f0 = brdf->eval(black, wo, wi), f1 = brdf->eval(white, wo, wi);
        const glm::vec3 mixed = use == ColourUse::Linear   ? c.baseColor * f1
                                : use == ColourUse::Affine ? f0 + c.baseColor * (f1 - f0)
                                                           : direct;
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(mixed[k], direct[k], 1e-5 * std::max(1.0f, std::abs(direct[k])))
                << brdf->name() << " (" << colourUseName(use) << ") channel " << k;
    }
}

// One evaluation at colour (1, 0, 0) stands for f(white) and f(black) only when both are grey
// (greyAffine): ggx is (its speed-up relies on it), and the red and green channels of f(red) then
// equal f(white) and f(black) at directions the probe did not use; an affine BRDF with a coloured
// offset is refused.
TEST(RelightColourUse, GreyAffineOneEvaluationGivesWhiteAndBlack) {
    plugins::BrdfParams params(glm::vec3(0.5f), 0.3f);
    const plugins::Brdf& ggx = *plugins::findBrdf("ggx");
    EXPECT_TRUE(greyAffine(ggx, params));
    plugins::BrdfParams black = params, white = params, red = params;
    black.baseColor = glm::vec3(0.0f);
    white.baseColor = glm::vec3(1.0f);
    red.baseColor = glm::vec3(1.0f, 0.0f, 0.0f);
    for (const glm::vec3& wo : {glm::vec3(0.3f, -0.2f, 0.8f), glm::vec3(0.7f, 0.1f, 0.2f)})
        for (const glm::vec3& wi : {glm::vec3(-0.25f, 0.3f, 0.7f), glm::vec3(-0.6f, 0.05f, 0.3f), glm::vec3(0.1f, 0.9f, 0.1f)}) {
            const glm::vec3 o = glm::normalize(wo), i = glm::normalize(wi);
            const glm::vec3 f = ggx.eval(red, o, i), f0 = ggx.eval(black, o, i), f1 = ggx.eval(white, o, i);
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(f.x, f1[k], 1e-6 * std::max(1.0f, f1[k]));
                EXPECT_NEAR(f.y, f0[k], 1e-6 * std::max(1.0f, f0[k]));
            }
        }
    // f = c / pi + (0.1, 0.2, 0.3) / pi: affine, not grey
    const ReColouredLambert tinted("tinted", [](const plugins::BrdfParams&, const glm::vec3& f, const glm::vec3& fWhite) {
        return f + glm::vec3(0.1f, 0.2f, 0.3f) * fWhite;
    });
    EXPECT_EQ(colourUseOf(tinted, params), ColourUse::Affine);
    EXPECT_FALSE(greyAffine(tinted, params));
}

TEST(RelightSphereLevel, FinerGridOnlyForALobeNarrowerThanHalfATexel) {
    scene::Scene scene = testing::makeRelightScene(); // GGX r = 0.3 on the box
    EXPECT_EQ(chooseSphereLevel(scene).level, 5) << chooseSphereLevel(scene).reason;
    scene.materials[1].roughness = 0.15f; // half-width 0.045 rad: under half a 32^2 texel only
    EXPECT_EQ(chooseSphereLevel(scene).level, 6);
    EXPECT_NE(chooseSphereLevel(scene).reason.find("shiny"), std::string::npos);
    scene.materials[1].roughness = 0.1f; // 0.020 rad: under half a 64^2 texel (0.033)
    EXPECT_EQ(chooseSphereLevel(scene).level, 7) << chooseSphereLevel(scene).reason;
    scene.objects[1].materialId = 1; scene.objects[2].materialId = 1; // the glossy material unused
    EXPECT_EQ(chooseSphereLevel(scene).level, 5);
}

TEST(RelightPreview, RefusesBadSettings) {
    RelightSettings s = testing::smallSettings();
    s.level = 9;
    EXPECT_FALSE(RelightPreview::create(testing::makeRelightScene(), s));
    s = testing::smallSettings();
    s.keep = 0;
    EXPECT_FALSE(RelightPreview::create(testing::makeRelightScene(), s));
}

} // namespace
} // namespace wavelit::relight
