// Coarse-to-fine: the first answer is the coarse grid's preview of the edited scene, and the full
// answer after the pending edits are merged equals a from-scratch build (≤ 1e-6 relative), for a
// drag of several frames (object moves, a roughness edit and a light move piled up).
#include "relight/coarse_to_fine.h"
#include "relight/relight_test_support.h"
#include "util/image_compare.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

namespace wavelit::relight {
namespace {

TEST(RelightCoarseToFine, FirstAnswerIsTheCoarseGridThenTheFullOneEqualsFromScratch) {
    using K = scene::EntityKind;
    scene::Scene scene = testing::makeRelightScene();
    const RelightSettings settings = testing::smallSettings();
    auto preview = CoarseToFinePreview::create(scene, settings, -1, 2);
    ASSERT_TRUE(preview);
    const RelightSettings coarseSettings = (*preview)->coarse().settings();
    EXPECT_EQ(coarseSettings.level, settings.level - 2);
    EXPECT_EQ(coarseSettings.width, settings.width / 2);
    const int w = settings.width, h = settings.height;
    const std::vector<std::tuple<scene::EntityRef, const char*, scene::PropertyValue>> frames = {
        {{K::Object, 4}, "translation", glm::vec3(0.2f, 0.5f, 0.0f)},
        {{K::Object, 4}, "translation", glm::vec3(0.4f, 0.5f, 0.1f)},
        {{K::Material, 2}, "roughness", 0.6f},
        {{K::Light, 7}, "position", glm::vec3(-1.0f, 2.2f, 0.3f)}};
    for (const auto& [ref, property, value] : frames) {
        scene::ChangeSet changes;
        ASSERT_TRUE(changes.setProperty(scene, ref, property, value));
        ASSERT_TRUE(changes.apply(scene));
        (*preview)->applyCoarse(scene, changes);
        EXPECT_TRUE((*preview)->finePending());
        auto coarseScratch = RelightPreview::create(scene, coarseSettings);
        ASSERT_TRUE(coarseScratch);
        EXPECT_LE(util::maxRelativeDifference((*preview)->image(w, h), (*coarseScratch)->image(w, h)), 1e-6);
    }
    const EditSummary fine = (*preview)->applyFine();
    EXPECT_EQ(fine.kind, "object"); // the merged set holds the object move
    EXPECT_FALSE((*preview)->finePending());
    auto scratch = RelightPreview::create(scene, settings);
    ASSERT_TRUE(scratch);
    const util::ImageRGB full = (*preview)->image(w, h);
    EXPECT_LE(util::maxRelativeDifference(full, (*scratch)->image()), 1e-6);
    // The coarse answer is an approximation of it, not the same image.
    EXPECT_GT(util::maxRelativeDifference((*preview)->coarseImage(w, h), full), 1e-3);
    EXPECT_EQ((*preview)->applyFine().pointsTouched, 0u); // nothing pending
}

// The corrected first answer (first_answer.h) is approximate: over a drag of two frames of an
// object its relative RMSE against the exact full preview stays within a bound, and well below the
// coarse image's own; with nothing pending it is the full image.
class RelightFirstAnswer : public ::testing::TestWithParam<bool> {};

TEST_P(RelightFirstAnswer, CorrectedFirstAnswerIsCloseToTheExactPreview) {
    using K = scene::EntityKind;
    scene::Scene scene = testing::makeRelightScene();
    const RelightSettings settings = testing::smallSettings();
    const bool defer = GetParam(); // the moved object's coarse points left stale during the drag
    auto preview = CoarseToFinePreview::create(scene, settings, -1, 2, defer);
    ASSERT_TRUE(preview);
    const int w = settings.width, h = settings.height;
    const util::ImageRGB stale = (*preview)->fine().image(); // before the drag
    EXPECT_EQ(util::maxRelativeDifference((*preview)->firstAnswer(w, h), stale), 0.0);
    for (const glm::vec3& to : {glm::vec3(0.2f, 0.5f, 0.0f), glm::vec3(0.25f, 0.5f, 0.05f)}) {
        scene::ChangeSet changes;
        ASSERT_TRUE(changes.setProperty(scene, {K::Object, 4}, "translation", to));
        ASSERT_TRUE(changes.apply(scene));
        (*preview)->applyCoarse(scene, changes);
    }
    auto scratch = RelightPreview::create(scene, settings);
    ASSERT_TRUE(scratch);
    const util::ImageRGB exact = (*scratch)->image();
    const double first = relativeRmse((*preview)->firstAnswer(w, h), exact);
    const double coarse = relativeRmse((*preview)->coarseImage(w, h), exact);
    const double before = relativeRmse(stale, exact);
    std::printf("relRMSE vs the exact preview: first answer %.4f, coarse image %.4f, image before the drag %.4f\n",
                first, coarse, before);
    EXPECT_GT(first, 0.0); // an approximation
    // Measured 0.176 (coarse image 1.67, the image before the drag 1.43).
    EXPECT_LE(first, 0.25);
    EXPECT_LE(first, 0.25 * coarse);
    EXPECT_LE(first, 0.25 * before); // the correction, not the stale image, makes it close
    if (defer) {
        EXPECT_GT(std::count((*preview)->coarse().deferred().begin(), (*preview)->coarse().deferred().end(), 1), 0);
    }
    (*preview)->applyFine();
    EXPECT_LE(util::maxRelativeDifference((*preview)->firstAnswer(w, h), exact), 1e-6); // then exact
    // and the coarse preview is a coarse build from scratch again (its deferred points rebuilt)
    auto coarseScratch = RelightPreview::create(scene, (*preview)->coarse().settings());
    ASSERT_TRUE(coarseScratch);
    EXPECT_LE(util::maxRelativeDifference((*preview)->coarseImage(w, h), (*coarseScratch)->image(w, h)), 1e-6);
    // A pending light move: the coarse image (the correction is for object and material edits).
    scene::ChangeSet light;
    ASSERT_TRUE(light.setProperty(scene, {K::Light, 7}, "position", glm::vec3(-1.0f, 2.2f, 0.3f)));
    ASSERT_TRUE(light.apply(scene));
    (*preview)->applyCoarse(scene, light);
    EXPECT_EQ(util::maxRelativeDifference((*preview)->firstAnswer(w, h), (*preview)->coarseImage(w, h)), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Defer, RelightFirstAnswer, ::testing::Bool());

} // namespace
} // namespace wavelit::relight
