// The shadow-field drag (shadow_field.h, drag_cache.h, docs/relighting.md §7.0e): the field is the
// ray-cast occlusion at its samples, the drag cache with an exact mask gives the exact terms, an
// incremental drag equals one step from the same cache, a far move touches only the region the
// object's old and new bounding cones reach, and a non-convex object's own points take their
// self-visibility from the drag start's points.
#include "relight/relight_preview.h"
#include "relight/relight_test_support.h"

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

constexpr size_t kBox = 1; // the near cube in makeRelightScene's objects
constexpr scene::EntityId kBoxId = 4;

double relDiff(const glm::vec3& a, const glm::vec3& b) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(a[c]) - double(b[c])) / std::max(std::abs(double(b[c])), 1e-4));
    return worst;
}

EditSummary move(RelightPreview& preview, scene::Scene& scene, const glm::vec3& to) {
    scene::ChangeSet changes;
    EXPECT_TRUE(changes.setProperty(scene, {scene::EntityKind::Object, kBoxId}, "translation", to));
    EXPECT_TRUE(changes.apply(scene));
    return preview.applyChanges(scene, changes);
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
    move(**preview, scene, glm::vec3(0.1f, 0.5f, 0.0f)); // an edit: `stale` read the state before it
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

double maxRelImageDiff(const util::ImageRGB& a, const util::ImageRGB& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(double(a.pixels[i][c]) - double(b.pixels[i][c])) /
                                        std::max(std::abs(double(b.pixels[i][c])), 1e-6));
    return worst;
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
        const EditSummary summary = move(**stepped, scene, to);
        EXPECT_EQ(summary.method, "shadowField");
        EXPECT_GT(summary.pointsTouched, 0u);
    }
    EXPECT_EQ(move(**direct, directScene, glm::vec3(0.5f, 0.5f, 0.2f)).method, "shadowField");
    EXPECT_TRUE((*stepped)->fieldApproximate());
    const util::ImageRGB a = (*stepped)->image(), b = (*direct)->image();
    EXPECT_LE(maxRelImageDiff(a, b), 1e-6);
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
    EXPECT_LE(maxRelImageDiff((*stepped)->image(), (*scratch)->image()), 1e-6);
    // The next translation rebuilds the caches and uses the field again.
    EXPECT_EQ(move(**stepped, scene, glm::vec3(0.4f, 0.5f, 0.0f)).method, "shadowField");
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
    const EditSummary summary = move(**preview, scene, glm::vec3(2.0f, -20.0f, -40.0f));
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

// Two unit cubes of half size h in one mesh, the second one step up and across: a non-convex
// object whose lower step's top sees the upper step's wall (self-shadow beyond the horizon).
std::shared_ptr<scene::TriangleMesh> stepMesh(float h) {
    auto m = testing::cubeMesh(h);
    const auto upper = testing::cubeMesh(h);
    const uint32_t base = uint32_t(m->positions.size());
    for (const glm::vec3& v : upper->positions) m->positions.push_back(v + glm::vec3(2.0f * h, h, 0.0f));
    for (uint32_t i : upper->indices) m->indices.push_back(base + i);
    return m;
}

// makeRelightScene with the box made the step (non-convex), resting on the ground, and the
// preview settings both step tests use (enough points on the step to measure its terms).
scene::Scene stepScene() {
    scene::Scene scene = testing::makeRelightScene();
    scene.objects[kBox].mesh = stepMesh(0.25f);
    scene.objects[kBox].transform.translation = {-0.1f, 0.25f, 0.0f};
    return scene;
}

RelightSettings stepSettings() {
    RelightSettings settings = testing::smallSettings();
    settings.width = 128;
    settings.height = 96;
    return settings;
}

// The points of `exact` on the box, which `other` (the same scene by another path) must hit
// identically: the points whose states the step tests compare.
void boxPoints(const RelightPreview& other, const RelightPreview& exact, std::vector<size_t>& out) {
    out.clear();
    for (size_t i = 0; i < exact.points().size(); ++i) {
        const PreviewPoint& p = exact.points()[i];
        if (!p.hit || p.object != kBox) continue;
        ASSERT_TRUE(other.points()[i] == p) << i;
        out.push_back(i);
    }
}

// (4) A non-convex moved object: every point of it (also where the camera hit stays put, on a
// face parallel to the drag) takes its self-visibility from the drag start's own-surface cache
// (field_drag.cpp nearestSelf: the nearest cached point on the same side) instead of rays. Self-visibility is translation-
// invariant, so that mask is the exact one up to the offset between the two points: against the
// exact drag it keeps nearly every texel and the terms close, where dropping self-shadowing
// altogether (every texel above the horizon lit) would not.
TEST(RelightShadowField, NonConvexObjectReusesItsOwnSelfVisibility) {
    scene::Scene scene = stepScene();
    const RelightSettings settings = stepSettings();
    auto fielded = RelightPreview::create(scene, settings);
    auto exact = RelightPreview::create(scene, settings);
    ASSERT_TRUE(fielded && exact);
    const TransferContext ctx = (*exact)->context();
    ASSERT_FALSE((*ctx.occluders)[kBox].convexFront && (*ctx.occluders)[kBox].convexBack);
    (*fielded)->enableShadowField(kBox);
    scene::Scene exactScene = scene;
    const glm::vec3 to(-0.06f, 0.25f, 0.03f);
    const EditSummary summary = move(**fielded, scene, to);
    move(**exact, exactScene, to);
    EXPECT_EQ(summary.method, "shadowField");
    EXPECT_GT(summary.selfMasksReused, 10u);
    EXPECT_LE(summary.selfMasksReused, summary.pointsRebuilt);

    std::vector<size_t> box;
    ASSERT_NO_FATAL_FAILURE(boxPoints(**fielded, **exact, box));
    const size_t own = box.size();
    size_t selfShadowed = 0, texels = 0, mismatched = 0, unshadowedWrong = 0;
    double sumSq = 0.0, sumRef = 0.0;
    for (size_t i : box) {
        const PointState& a = (*fielded)->states()[i];
        const PointState& b = (*exact)->states()[i];
        for (size_t w = 0; w < b.above.size(); ++w) {
            const uint64_t selfB = b.above[w] & ~b.lit[w], selfA = a.above[w] & ~a.lit[w];
            texels += size_t(__builtin_popcountll(b.above[w]));
            mismatched += size_t(__builtin_popcountll(selfA ^ selfB));
            unshadowedWrong += size_t(__builtin_popcountll(selfB)); // what "no self mask" gets wrong
        }
        selfShadowed += anyBit(b.above) && b.above != b.lit ? 1 : 0;
        const double ref = double(b.envTerm.y), got = double(a.envTerm.y);
        sumSq += (got - ref) * (got - ref);
        sumRef += ref;
    }
    ASSERT_GT(own, 50u);
    EXPECT_GT(selfShadowed, own / 10); // the shape shadows itself: the masks matter
    EXPECT_GT(unshadowedWrong, texels / 50);
    // Measured: 65 self texels differ where no mask would miss 1139; the env terms of the
    // object's own points at relRMSE 0.008. Before the points on the step's top (a face parallel
    // to the drag: the same camera hit) were rebuilt, they kept their stale masks: 201 and 0.24.
    EXPECT_LT(double(mismatched), 0.1 * double(unshadowedWrong)) << mismatched << " of " << unshadowedWrong;
    const double relRmse = std::sqrt(sumSq / double(own)) / (sumRef / double(own));
    EXPECT_LT(relRmse, 0.03);
    std::printf("own points %zu, self-shadowed %zu, reused %zu; self texels wrong %zu of %zu (no mask: %zu); env term relRMSE %.4f\n",
                own, selfShadowed, summary.selfMasksReused, mismatched, texels, unshadowedWrong, relRmse);
}

// The relative RMSE of `carried`'s terms (environment, first light) on the box's points against
// `exact`'s, which must hit them identically; `own` gets how many there are, `withoutT` how many
// carry no T (carried states).
double ownTermsRelRmse(const RelightPreview& carried, const RelightPreview& exact, size_t& own, size_t& withoutT) {
    std::vector<size_t> box;
    boxPoints(carried, exact, box);
    own = box.size();
    withoutT = 0;
    double sumSq = 0.0, sumRef = 0.0;
    for (size_t i : box) {
        const PointState& a = carried.states()[i];
        const PointState& b = exact.states()[i];
        withoutT += a.transfer.index.empty() ? 1 : 0;
        for (const auto& [got, ref] : {std::pair{a.envTerm, b.envTerm}, std::pair{a.lightTerms.at(0), b.lightTerms.at(0)}}) {
            sumSq += double(glm::dot(got - ref, got - ref));
            sumRef += double(ref.x + ref.y + ref.z) / 3.0;
        }
    }
    return own ? std::sqrt(sumSq / double(2 * own * 3)) / (sumRef / double(2 * own)) : 0.0;
}

// (6) carriedLobeCut: a narrow lobe's carried terms summed only within two caps of the mirror
// direction stay as close to the exact drag as the full sum (what lies beyond holds a few percent
// of the lobe at most), and the cut does leave texels out (the terms differ).
TEST(RelightShadowField, CarriedLobeCutKeepsTheNarrowLobesTermsClose) {
    scene::Scene scene = testing::makeRelightScene();
    scene.materials[1].roughness = 0.08f; // the box's "shiny": narrower than a 32^2 texel
    RelightSettings settings = testing::smallSettings();
    settings.width = 64;
    settings.height = 48;
    settings.level = 5;
    settings.keep = size_t(1) << (2 * settings.level);
    auto cut = RelightPreview::create(scene, settings);
    auto full = RelightPreview::create(scene, settings);
    auto exact = RelightPreview::create(scene, settings);
    ASSERT_TRUE(cut && full && exact);
    ASSERT_TRUE((*cut)->context().materials->at(1).narrow);
    ShadowFieldSettings field;
    field.reuseOwnStates = true;
    (*full)->enableShadowField(kBox, field);
    field.carriedLobeCut = 2.0f;
    (*cut)->enableShadowField(kBox, field);
    scene::Scene fullScene = scene, exactScene = scene;
    for (const glm::vec3& to : {glm::vec3(0.03f, 0.5f, 0.02f), glm::vec3(0.05f, 0.5f, 0.03f)}) {
        move(**cut, scene, to);
        move(**full, fullScene, to);
        move(**exact, exactScene, to);
    }
    size_t own = 0, withoutT = 0, ownFull = 0;
    double cutError = 0.0, fullError = 0.0;
    ASSERT_NO_FATAL_FAILURE(cutError = ownTermsRelRmse(**cut, **exact, own, withoutT));
    ASSERT_NO_FATAL_FAILURE(fullError = ownTermsRelRmse(**full, **exact, ownFull, withoutT));
    ASSERT_GT(own, 20u);
    size_t differ = 0;
    for (size_t i = 0; i < (*cut)->states().size(); ++i)
        differ += (*cut)->states()[i].envTerm != (*full)->states()[i].envTerm ? 1 : 0;
    std::printf("own points %zu: terms relRMSE against the exact drag %.4f with the cut, %.4f without; %zu "
                "points' terms differ\n", own, cutError, fullError, differ);
    EXPECT_GT(differ, 0u);
    EXPECT_LE(cutError, fullError + 0.01);
}

// (5) With reuseOwnStates the moved object's points take their visibility (self and the other
// objects' occlusion) from the drag start's nearest point of it, with no rays and no T, and their
// terms untruncated with their own BRDF and view direction (carriedVisibilityState). Against the
// exact drag their terms stay close; the first other edit rebuilds them, and the preview is
// create()'s on the edited scene again, T included. A second drag (its caches rebuilt at its
// first step, from where the object was before that step) is a drag from a field enabled there.
TEST(RelightShadowField, CarriedOwnStatesAreCloseAndSettleToExact) {
    scene::Scene scene = stepScene();
    RelightSettings settings = stepSettings();
    // Every coefficient kept: the carried terms are untruncated, so T's truncation would
    // otherwise be most of their difference from the exact drag.
    settings.keep = size_t(1) << (2 * settings.level);
    auto carried = RelightPreview::create(scene, settings);
    auto exact = RelightPreview::create(scene, settings);
    ASSERT_TRUE(carried && exact);
    ShadowFieldSettings field;
    field.reuseOwnStates = true;
    (*carried)->enableShadowField(kBox, field);
    scene::Scene exactScene = scene;
    EditSummary summary;
    for (const glm::vec3& to : {glm::vec3(-0.08f, 0.25f, 0.02f), glm::vec3(-0.06f, 0.25f, 0.03f)}) {
        summary = move(**carried, scene, to);
        move(**exact, exactScene, to);
    }
    EXPECT_EQ(summary.method, "shadowField");
    EXPECT_TRUE((*carried)->fieldApproximate());

    size_t own = 0, withoutT = 0;
    double relRmse = 0.0;
    ASSERT_NO_FATAL_FAILURE(relRmse = ownTermsRelRmse(**carried, **exact, own, withoutT));
    ASSERT_GT(own, 50u);
    // Every own point of a 2-step drag is carried but those with no cached point near them.
    EXPECT_EQ(summary.statesCarried, withoutT);
    EXPECT_GT(summary.statesCarried, own * 9 / 10);
    EXPECT_LT(summary.pointsRebuilt, own / 10);
    EXPECT_LT(relRmse, 0.05);
    std::printf("own points %zu, carried %zu, rebuilt %zu; own terms relRMSE %.4f against the exact drag\n", own,
                summary.statesCarried, summary.pointsRebuilt, relRmse);

    scene::ChangeSet env;
    ASSERT_TRUE(env.setProperty(scene, {scene::EntityKind::Environment, scene::kInvalidId}, "intensity", 1.5f));
    ASSERT_TRUE(env.apply(scene));
    EXPECT_TRUE((*carried)->applyChanges(scene, env).method.empty());
    EXPECT_FALSE((*carried)->fieldApproximate());
    auto scratch = RelightPreview::create(scene, settings);
    ASSERT_TRUE(scratch);
    EXPECT_LE(maxRelImageDiff((*carried)->image(), (*scratch)->image()), 1e-6);
    for (size_t i = 0; i < (*scratch)->states().size(); ++i) {
        EXPECT_EQ((*carried)->states()[i].transfer.index, (*scratch)->states()[i].transfer.index) << i;
        EXPECT_EQ((*carried)->states()[i].transfer.value, (*scratch)->states()[i].transfer.value) << i;
    }

    // The second drag, on from there: the field kept, the caches rebuilt at its first step from
    // where the object was then — the same preview as a field enabled there.
    auto fresh = RelightPreview::create(scene, settings);
    ASSERT_TRUE(fresh);
    (*fresh)->enableShadowField(kBox, field);
    scene::Scene freshScene = scene;
    ASSERT_TRUE(env.apply(exactScene));
    (*exact)->applyChanges(exactScene, env);
    for (const glm::vec3& to : {glm::vec3(-0.04f, 0.25f, 0.04f), glm::vec3(-0.02f, 0.25f, 0.05f)}) {
        summary = move(**carried, scene, to);
        move(**fresh, freshScene, to);
        move(**exact, exactScene, to);
    }
    EXPECT_EQ(summary.method, "shadowField");
    EXPECT_LE(maxRelImageDiff((*carried)->image(), (*fresh)->image()), 1e-6);
    ASSERT_NO_FATAL_FAILURE(relRmse = ownTermsRelRmse(**carried, **exact, own, withoutT));
    EXPECT_GT(summary.statesCarried, own * 9 / 10);
    EXPECT_LT(relRmse, 0.05);
    std::printf("second drag: own points %zu, carried %zu; own terms relRMSE %.4f against the exact drag\n", own,
                summary.statesCarried, relRmse);
}

} // namespace
} // namespace wavelit::relight
