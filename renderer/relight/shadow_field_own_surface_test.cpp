// The shadow-field drag's moved object itself (docs/relighting.md §7.0e, §7.0j, §7.0k): a
// non-convex object's own points take their self-visibility from the drag start's points, with
// reuseOwnStates its points carry their whole visibility and settle to create() exactly, and the
// carried lobe cut keeps a narrow lobe's terms close to the full sum.
#include "relight/relight_preview.h"
#include "relight/relight_test_support.h"
#include "relight/shadow_field_test_support.h"
#include "util/image_compare.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace wavelit::relight {
namespace {

using testing::kBox;
using testing::moveBox;

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
// (FieldDrag::nearestOwn: the nearest cached point on the same side) instead of rays.
// Self-visibility is translation-invariant, so that mask is the exact one up to the offset
// between the two points: against the
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
    const EditSummary summary = moveBox(**fielded, scene, to);
    moveBox(**exact, exactScene, to);
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
        summary = moveBox(**carried, scene, to);
        moveBox(**exact, exactScene, to);
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
    EXPECT_LE(util::maxRelativeDifference((*carried)->image(), (*scratch)->image()), 1e-6);
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
        summary = moveBox(**carried, scene, to);
        moveBox(**fresh, freshScene, to);
        moveBox(**exact, exactScene, to);
    }
    EXPECT_EQ(summary.method, "shadowField");
    EXPECT_LE(util::maxRelativeDifference((*carried)->image(), (*fresh)->image()), 1e-6);
    ASSERT_NO_FATAL_FAILURE(relRmse = ownTermsRelRmse(**carried, **exact, own, withoutT));
    EXPECT_GT(summary.statesCarried, own * 9 / 10);
    EXPECT_LT(relRmse, 0.05);
    std::printf("second drag: own points %zu, carried %zu; own terms relRMSE %.4f against the exact drag\n", own,
                summary.statesCarried, relRmse);
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
        moveBox(**cut, scene, to);
        moveBox(**full, fullScene, to);
        moveBox(**exact, exactScene, to);
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

} // namespace
} // namespace wavelit::relight
