// The shadow-field drag (shadow_field.h, drag_cache.h, docs/relighting.md §7.0e): a prepared field
// is installed only on the state it read, the field is the ray-cast occlusion at its samples, the
// drag cache with an exact mask gives the exact terms, an incremental drag equals one step from
// the same cache, and a far move touches only the region the object's old and new bounding cones
// reach. The moved object's own surface: shadow_field_own_surface_test.cpp.
#include "relight/relight_preview.h"
#include "relight/relight_test_support.h"
#include "relight/shadow_field_test_support.h"
#include "util/image_compare.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace wavelit::relight {
namespace {

using testing::kBox;
using testing::moveBox;

double relDiff(const glm::vec3& a, const glm::vec3& b) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(a[c]) - double(b[c])) / std::max(std::abs(double(b[c])), 1e-4));
    return worst;
}

// (0) prepareShadowField with its cancel flag set gives nothing; unset, what enableShadowField
// installs, and installShadowField refuses it once an edit came in between.
TEST(RelightShadowField, PreparedFieldIsCancelledOrInstalledOnlyOnTheStateItRead) {
    scene::Scene scene = testing::makeRelightScene();
    auto preview = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(preview);
    std::atomic<bool> cancel{true};
    EXPECT_FALSE((*preview)->prepareShadowField(kBox, {}, &cancel).valid());
    cancel = false;
    RelightPreview::PreparedShadowField prepared = (*preview)->prepareShadowField(kBox, {}, &cancel);
    ASSERT_TRUE(prepared.valid());
    EXPECT_GT(prepared.info.cachedPoints, 0u);
    RelightPreview::PreparedShadowField stale = (*preview)->prepareShadowField(kBox);
    EXPECT_TRUE((*preview)->installShadowField(std::move(prepared)));
    EXPECT_TRUE((*preview)->fieldDragReady(kBox));
    moveBox(**preview, scene, glm::vec3(0.1f, 0.5f, 0.0f)); // an edit: `stale` read the state before it
    EXPECT_FALSE((*preview)->installShadowField(std::move(stale)));
}

// (1a) At every sample position the field's mask is the ray-cast one, bit for bit.
TEST(RelightShadowField, MaskAtASampleIsTheRayCastMask) {
    auto preview = RelightPreview::create(testing::makeRelightScene(), testing::smallSettings());
    ASSERT_TRUE(preview);
    ShadowFieldSettings settings;
    settings.shells = 6;
    settings.directionLevel = 3;
    (*preview)->enableShadowField(kBox, settings);
    const ShadowField& field = *(*preview)->shadowField();
    const TransferContext ctx = (*preview)->context();
    const ObjectOccluder& box = (*ctx.occluders)[kBox];
    TexelBits all = makeBits(ctx.dirs->count());
    for (size_t t = 0; t < ctx.dirs->count(); ++t) setBit(all, t);
    size_t blocked = 0;
    for (size_t shell = 0; shell < field.shells(); ++shell)
        for (size_t d = 0; d < field.directions(); ++d) {
            const glm::vec3 offset = field.sampleOffset(shell, d);
            const glm::vec3 origin = box.bounds.centre + offset;
            const TexelBits want = castOcclusion(box, origin, *ctx.dirs, coneTexels(box.bounds, origin, *ctx.dirs, all));
            const uint64_t* got = field.lookup(offset);
            ASSERT_EQ(got, field.sampleMask(shell, d)) << shell << " " << d; // the nearest sample is itself
            for (size_t w = 0; w < want.size(); ++w) ASSERT_EQ(got[w], want[w]) << shell << " " << d;
            blocked += anyBit(want) ? 1 : 0;
        }
    EXPECT_GT(blocked, field.directions()); // the masks are not trivially empty
}

// (1b) With a point's exact (ray-cast) mask — what the field holds at a sample — the drag cache
// gives the exact preview's terms (all coefficients kept: the truncation is the only other
// difference, drag_cache.h; <= 1e-5 relative).
TEST(RelightShadowField, CacheWithTheExactMaskGivesTheExactTerms) {
    RelightSettings settings = testing::smallSettings();
    settings.keep = size_t(1) << (2 * settings.level);
    auto preview = RelightPreview::create(testing::makeRelightScene(), settings);
    ASSERT_TRUE(preview);
    (*preview)->enableShadowField(kBox);
    const TransferContext ctx = (*preview)->context();
    const ObjectOccluder& box = (*ctx.occluders)[kBox];
    const auto& caches = *(*preview)->dragCaches();
    size_t checked = 0, shadowed = 0;
    for (size_t i = 0; i < caches.size(); ++i) {
        if (!caches[i].valid) continue;
        const PreviewPoint& p = (*preview)->points()[i];
        const PointState& exact = (*preview)->states()[i];
        const glm::vec3 origin = rayOrigin(p);
        const TexelBits mask = castOcclusion(box, origin, *ctx.dirs, coneTexels(box.bounds, origin, *ctx.dirs, caches[i].visible));
        PointState s = exact;
        applyDragMask(caches[i], mask.data(), box.bounds, origin, (*preview)->fieldEnvTexels(), s, &box.bvh);
        EXPECT_LE(relDiff(s.envTerm, exact.envTerm), 1e-5) << i;
        EXPECT_LE(relDiff(s.envTerm0, exact.envTerm0), 1e-5) << i;
        ASSERT_EQ(s.lightTerms.size(), exact.lightTerms.size());
        for (size_t k = 0; k < s.lightTerms.size(); ++k) EXPECT_LE(relDiff(s.lightTerms[k], exact.lightTerms[k]), 1e-5) << i << " light " << k;
        ++checked;
        shadowed += anyBit(mask) ? 1 : 0;
    }
    EXPECT_GT(checked, 100u);
    EXPECT_GT(shadowed, 20u);
}

// (2) A drag in three steps equals one step to the same place from the same field and caches
// (<= 1e-6): the result depends on the cache and the new position only. And the first other edit
// restores the exact preview: equal to create() on the edited scene.
TEST(RelightShadowField, IncrementalDragEqualsOneStepWithTheSameField) {
    scene::Scene scene = testing::makeRelightScene();
    auto stepped = RelightPreview::create(scene, testing::smallSettings());
    auto direct = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(stepped && direct);
    const util::ImageRGB before = (*stepped)->image();
    (*stepped)->enableShadowField(kBox);
    (*direct)->enableShadowField(kBox);
    scene::Scene directScene = scene;
    for (const glm::vec3& to : {glm::vec3(0.2f, 0.5f, 0.1f), glm::vec3(0.35f, 0.5f, 0.2f), glm::vec3(0.5f, 0.5f, 0.2f)}) {
        const EditSummary summary = moveBox(**stepped, scene, to);
        EXPECT_EQ(summary.method, "shadowField");
        EXPECT_GT(summary.pointsTouched, 0u);
    }
    EXPECT_EQ(moveBox(**direct, directScene, glm::vec3(0.5f, 0.5f, 0.2f)).method, "shadowField");
    EXPECT_TRUE((*stepped)->fieldApproximate());
    const util::ImageRGB a = (*stepped)->image(), b = (*direct)->image();
    EXPECT_LE(util::maxRelativeDifference(a, b), 1e-6);
    double change = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) change += std::abs(a.pixels[i].x - before.pixels[i].x);
    EXPECT_GT(change, 1e-3); // the drag changed the image

    // Another edit (the environment's intensity: nothing per point by itself) settles the field's
    // points: the preview is create()'s on the edited scene again.
    scene::ChangeSet env;
    ASSERT_TRUE(env.setProperty(scene, {scene::EntityKind::Environment, scene::kInvalidId}, "intensity", 1.5f));
    ASSERT_TRUE(env.apply(scene));
    EXPECT_TRUE((*stepped)->applyChanges(scene, env).method.empty());
    EXPECT_FALSE((*stepped)->fieldApproximate());
    auto scratch = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(scratch);
    EXPECT_LE(util::maxRelativeDifference((*stepped)->image(), (*scratch)->image()), 1e-6);
    // The next translation rebuilds the caches and uses the field again.
    EXPECT_EQ(moveBox(**stepped, scene, glm::vec3(0.4f, 0.5f, 0.0f)).method, "shadowField");
}

// (3) Moving the box far away (40 m, below the ground's horizon) through its field touches only
// points whose camera hit changed or whose upper hemisphere the box's old or new bounding cone
// reaches; every other point keeps its terms bit for bit.
TEST(RelightShadowField, FarMoveTouchesOnlyTheShadowRegion) {
    scene::Scene scene = testing::makeRelightScene();
    auto preview = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(preview);
    (*preview)->enableShadowField(kBox);
    const std::vector<PreviewPoint> pointsBefore = (*preview)->points();
    const std::vector<PointState> before = (*preview)->states();
    const TransferContext ctx = (*preview)->context();
    const BoundingSphere oldBounds = (*ctx.occluders)[kBox].bounds;
    const EditSummary summary = moveBox(**preview, scene, glm::vec3(2.0f, -20.0f, -40.0f));
    EXPECT_EQ(summary.method, "shadowField");
    const BoundingSphere newBounds = (*(*preview)->context().occluders)[kBox].bounds;
    const auto& touched = (*preview)->lastTouched();
    size_t inRegion = 0, hitChanged = 0, touchedCount = 0;
    for (size_t i = 0; i < pointsBefore.size(); ++i) {
        const PreviewPoint& p = (*preview)->points()[i];
        touchedCount += touched[i];
        if (!(pointsBefore[i] == p)) {
            ++hitChanged;
            continue;
        }
        if (!p.hit) continue;
        const TexelBits& above = before[i].above;
        const bool region = anyBit(coneTexels(oldBounds, rayOrigin(p), *ctx.dirs, above)) ||
                            anyBit(coneTexels(newBounds, rayOrigin(p), *ctx.dirs, above));
        inRegion += region ? 1 : 0;
        if (!region) {
            EXPECT_FALSE(touched[i]) << i;
            EXPECT_EQ(before[i].envTerm, (*preview)->states()[i].envTerm) << i;
            EXPECT_EQ(before[i].lightTerms, (*preview)->states()[i].lightTerms) << i;
        }
    }
    EXPECT_EQ(summary.pointsTouched, touchedCount);
    EXPECT_LE(touchedCount, inRegion + hitChanged);
    EXPECT_GT(touchedCount, hitChanged); // the box's old shadow went away: not trivially zero
    EXPECT_GT(hitChanged, 0u);          // the box's own pixels
    EXPECT_GT((*preview)->hitCount(), 100u);
}

} // namespace
} // namespace wavelit::relight
