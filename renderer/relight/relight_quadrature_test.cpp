// The preview's products against brute force (architecture.md §8 "wavelet operations against
// pixel-domain brute force"), and the shadow region of a moved object (pointsTouched by count).
#include "relight/environment_factor.h"
#include "relight/light_projection.h"
#include "relight/relight_preview.h"
#include "relight/relight_test_support.h"
#include "wavelet/equirect_resample.h"
#include "wavelet/haar.h"
#include "util/hemisphere_sampling.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace wavelit::relight {
namespace {

double relativeError(const glm::dvec3& got, const glm::dvec3& want) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(got[c] - want[c]) / std::max(std::abs(want[c]), 1e-12));
    return worst;
}

// At full coefficients (K = 4^n) the wavelet-domain 4 pi <T, L> equals the texel quadrature
// sum_t T(t) L(t) dOmega_t, with T from the factors at each texel and L from the factor's texels.
TEST(RelightQuadrature, EnvironmentTermEqualsTexelQuadratureAtFullCoefficients) {
    RelightSettings settings = testing::smallSettings();
    settings.keep = size_t(1) << (2 * settings.level);
    auto preview = RelightPreview::create(testing::makeRelightScene(), settings);
    ASSERT_TRUE(preview);
    const TransferContext ctx = (*preview)->context();
    std::array<wavelet::SquareGrid, 3> env;
    for (int c = 0; c < 3; ++c)
        env[size_t(c)] = wavelet::inverseHaar(
            wavelet::HaarImage{settings.level, ctx.environment->coefficients[size_t(c)]});
    size_t checked = 0;
    for (size_t i = 0; i < (*preview)->points().size(); i += 7) {
        const PreviewPoint& p = (*preview)->points()[i];
        if (!p.hit) continue;
        const PointState& s = (*preview)->states()[i];
        glm::dvec3 brute(0.0);
        for (size_t t = 0; t < ctx.dirs->count(); ++t) {
            const glm::dvec3 T(transferAt(ctx, p, s, t));
            for (int c = 0; c < 3; ++c) brute[c] += T[c] * env[size_t(c)].values[t] * ctx.dirs->texelSolidAngle();
        }
        EXPECT_LE(relativeError(glm::dvec3(s.envTerm), brute), 1e-4) << "point " << i;
        ++checked;
    }
    EXPECT_GT(checked, 10u);
}

// The same identity for a light: <T, L_k> from the light's texels equals the Haar-domain inner
// product of T's full coefficients with the light factor's (Parseval), where no light texel is
// shadowed (an open point, so the shadow-ray branch does not enter).
TEST(RelightQuadrature, LightTermEqualsHaarInnerProductAtFullCoefficients) {
    RelightSettings settings = testing::smallSettings();
    settings.keep = size_t(1) << (2 * settings.level);
    scene::Scene scene = testing::makeRelightScene();
    auto preview = RelightPreview::create(scene, settings);
    ASSERT_TRUE(preview);
    const TransferContext ctx = (*preview)->context();
    size_t checked = 0;
    for (size_t i = 0; i < (*preview)->points().size(); i += 5) {
        const PreviewPoint& p = (*preview)->points()[i];
        const PointState& s = (*preview)->states()[i];
        if (!p.hit) continue;
        // A narrow glossy lobe sees a light where it is, not as T's texel average (point_transfer.h);
        // those points are checked against direct evaluation below.
        if ((*ctx.materials)[std::min<size_t>(p.material, ctx.materials->size() - 1)].narrow) continue;
        for (size_t k = 0; k < scene.lighting.lights.size(); ++k) {
            const auto entries = projectLight(unitPowerLight(scene.lighting.lights[k]), rayOrigin(p), *ctx.dirs);
            bool open = true;
            std::array<wavelet::SquareGrid, 3> light{wavelet::SquareGrid(settings.level),
                                                     wavelet::SquareGrid(settings.level),
                                                     wavelet::SquareGrid(settings.level)};
            for (const TexelWeight& e : entries) {
                open = open && testBit(s.lit, e.texel) == testBit(s.above, e.texel);
                for (const Occlusion& o : s.occlusions) open = open && !testBit(o.blocked, e.texel);
                for (int c = 0; c < 3; ++c)
                    light[size_t(c)].values[e.texel] = e.weight[c] / ctx.dirs->texelSolidAngle();
            }
            if (!open) continue;
            glm::dvec3 haar(0.0);
            for (int c = 0; c < 3; ++c) {
                const auto lc = wavelet::forwardHaar(light[size_t(c)]).coeffs;
                for (size_t n = 0; n < s.transfer.index.size(); ++n)
                    haar[c] += double(s.transfer.value[n][c]) * lc[s.transfer.index[n]];
                haar[c] *= 4.0 * std::numbers::pi;
            }
            const glm::dvec3 term(s.lightTerms[k]);
            if (glm::length(haar) == 0.0) continue;
            EXPECT_LE(relativeError(term, haar), 1e-4) << "point " << i << " light " << k;
            ++checked;
        }
    }
    EXPECT_GT(checked, 10u);
}

// On a narrow glossy lobe a point light's term is f x cosine at the light's own direction times
// I / D^2 (what the path tracer's next-event estimate computes), not T's average over the texel.
TEST(RelightQuadrature, NarrowLobeSeesAPointLightAtItsDirection) {
    RelightSettings settings = testing::smallSettings();
    scene::Scene scene = testing::makeRelightScene();
    scene.materials[1].roughness = 0.05f; // the box's ggx: a lobe far narrower than a 16^2 texel
    // The bulb where the box's top face mirrors the camera (top centre (0, 1, 0), camera
    // (0, 2.5, 5)), so points there see it inside their lobe.
    scene.lighting.lights[0].position = {0.0f, 1.6f, -2.0f};
    auto preview = RelightPreview::create(scene, settings);
    ASSERT_TRUE(preview);
    const TransferContext ctx = (*preview)->context();
    const scene::Light& bulb = scene.lighting.lights[0];
    ASSERT_EQ(bulb.type, scene::LightType::Point);
    size_t checked = 0;
    for (size_t i = 0; i < (*preview)->points().size(); ++i) {
        const PreviewPoint& p = (*preview)->points()[i];
        const PointState& s = (*preview)->states()[i];
        if (!p.hit || p.material != 1) continue;
        const ResolvedMaterial& m = (*ctx.materials)[1];
        ASSERT_TRUE(m.narrow);
        const glm::vec3 origin = rayOrigin(p), toLight = bulb.position - origin;
        const glm::vec3 dir = glm::normalize(toLight);
        const size_t texel = ctx.dirs->texelOf(dir);
        if (!testBit(s.lit, texel)) continue;
        bool open = true;
        for (const Occlusion& o : s.occlusions) open = open && !testBit(o.blocked, texel);
        if (!open) continue;
        const util::Frame frame = util::Frame::fromNormal(p.shading);
        const glm::vec3 wo = frame.toLocal(p.wo), wi = frame.toLocal(dir);
        if (glm::dot(wi, glm::vec3(-wo.x, -wo.y, wo.z)) < m.cosCap || wi.z <= 0.0f) continue;
        // White (the affine class's primary parameters) and black, mixed with the colour.
        const glm::vec3 f1 = m.brdf->eval(m.params, wo, wi), f0 = m.brdf->eval(m.black, wo, wi);
        const float irradiance = float(1.0 / (4.0 * std::numbers::pi)) / glm::dot(toLight, toLight) * wi.z;
        const glm::dvec3 expected(f1 * irradiance), expected0(f0 * irradiance);
        EXPECT_LE(relativeError(glm::dvec3(s.lightTerms[0]), expected), 1e-4) << "point " << i;
        EXPECT_LE(relativeError(glm::dvec3(s.lightTerms0[0]), expected0), 1e-4) << "point " << i;
        ++checked;
    }
    EXPECT_GT(checked, 0u);
}

// The reduced equirect keeps the map's integral over the sphere (solid-angle-weighted blocks).
TEST(RelightEnvironment, ReducedEquirectKeepsTheEnergy) {
    util::ImageRGB image(512, 256);
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 512; ++x) image.at(x, y) = glm::vec3(float((x * 7 + y * 13) % 17), float(y), 1.0f);
    image.at(100, 40) = glm::vec3(5e4f); // a one-texel sun
    const auto reduced = reduceEquirect(image, 5);
    EXPECT_EQ(reduced->width, 256);
    const glm::dvec3 a = wavelet::equirectEnergy(image), b = wavelet::equirectEnergy(*reduced);
    EXPECT_LE(relativeError(b, a), 1e-5);
}

// The float texelOf is the wavelet core's octahedral map: every texel centre maps to its texel.
TEST(RelightTexels, TexelOfFindsEveryTexelCentre) {
    for (int level : {3, 5, 6}) {
        const TexelDirections dirs(level);
        for (size_t t = 0; t < dirs.count(); ++t) ASSERT_EQ(dirs.texelOf(dirs.direction(t)), t) << level;
    }
}

// aboveBoth is the per-texel test it replaced (glm::dot > 0 against both normals), bit for bit,
// at every level (level 1's 4 texels are one padded word), for random and axis-aligned normals
// (texel centres on a great circle through an axis give dot products of exactly 0).
TEST(RelightTexels, AboveBothIsThePerTexelHorizonTest) {
    std::mt19937 rng(5);
    std::normal_distribution<float> gauss;
    for (int level : {1, 3, 5, 6}) {
        const TexelDirections dirs(level);
        std::vector<glm::vec3> normals = {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}};
        for (int k = 0; k < 40; ++k) normals.push_back(glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng))));
        size_t set = 0;
        for (size_t i = 0; i + 1 < normals.size(); ++i) {
            const glm::vec3 a = normals[i], b = glm::normalize(normals[i] + 0.5f * normals[i + 1]);
            const TexelBits got = dirs.aboveBoth(a, b);
            TexelBits want = makeBits(dirs.count());
            for (size_t t = 0; t < dirs.count(); ++t)
                if (glm::dot(dirs.direction(t), a) > 0.0f && glm::dot(dirs.direction(t), b) > 0.0f) setBit(want, t);
            ASSERT_EQ(got, want) << level << " " << i;
            for (uint64_t w : got) set += size_t(__builtin_popcountll(w));
        }
        EXPECT_GT(set, dirs.count()); // not trivially empty
    }
}

// Moving the far cube (below the ground's horizon, 40 m away) touches exactly the points whose
// upper hemisphere its old or new bounding cone reaches — none on the ground or the near cube's
// visible faces — and leaves every other point's state as it was.
TEST(RelightRegion, MovingAFarObjectTouchesOnlyItsShadowRegion) {
    scene::Scene scene = testing::makeRelightScene();
    auto preview = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(preview);
    const std::vector<PointState> before = (*preview)->states();
    const TransferContext ctx = (*preview)->context();
    const BoundingSphere oldBounds = (*ctx.occluders)[2].bounds;
    scene::ChangeSet changes;
    ASSERT_TRUE(changes.setProperty(scene, {scene::EntityKind::Object, 5}, "translation",
                                    glm::vec3(2.0f, -20.0f, -40.0f)));
    ASSERT_TRUE(changes.apply(scene));
    const EditSummary summary = (*preview)->applyChanges(scene, changes);
    const BoundingSphere newBounds = (*(*preview)->context().occluders)[2].bounds;
    size_t inRegion = 0;
    for (size_t i = 0; i < (*preview)->points().size(); ++i) {
        const PreviewPoint& p = (*preview)->points()[i];
        if (!p.hit) continue;
        const TexelBits& above = before[i].above;
        if (anyBit(coneTexels(oldBounds, rayOrigin(p), *ctx.dirs, above)) ||
            anyBit(coneTexels(newBounds, rayOrigin(p), *ctx.dirs, above)))
            ++inRegion;
        else
            EXPECT_EQ(before[i].transfer.value, (*preview)->states()[i].transfer.value) << i;
    }
    EXPECT_EQ(summary.pointsTouched, inRegion);
    EXPECT_EQ(summary.pointsTouched, 0u);
    EXPECT_GT((*preview)->hitCount(), 100u);
    // The near cube, moved, does touch points: the counts are not trivially zero.
    scene::ChangeSet near;
    ASSERT_TRUE(near.setProperty(scene, {scene::EntityKind::Object, 4}, "translation", glm::vec3(0.3f, 0.5f, 0.0f)));
    ASSERT_TRUE(near.apply(scene));
    EXPECT_GT((*preview)->applyChanges(scene, near).pointsTouched, 50u);
}

} // namespace
} // namespace wavelit::relight
