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

// Field drags (enableFieldDrags): the first translation frame starts the object's field and drag
// caches on a thread of their own and is the coarse first answer; once they are in, frames go to
// the full preview through the field — its image is the first answer, closer to the exact preview
// than the coarse first answer of the same frames — and applyFine makes both previews exact
// again. A second drag reuses the field (caches rebuilt); another edit during it, a field prepared
// before the drag, a build applyFine cancels and one still running when the preview goes are
// handled.
TEST(RelightCoarseToFine, FieldDragFramesGoToTheFullPreviewAndSettleExactly) {
    using K = scene::EntityKind;
    scene::Scene scene = testing::makeRelightScene();
    RelightSettings settings = testing::smallSettings();
    settings.width = 40;
    settings.height = 32;
    auto preview = CoarseToFinePreview::create(scene, settings, -1, 2, true);
    auto plain = CoarseToFinePreview::create(scene, settings, -1, 2, true); // no field drags
    ASSERT_TRUE(preview && plain);
    ShadowFieldSettings field;
    field.reuseOwnStates = true;
    (*preview)->enableFieldDrags(field);
    const int w = settings.width, h = settings.height;
    constexpr size_t kBox = 1;
    auto frame = [&](const glm::vec3& to, bool alsoPlain) {
        scene::ChangeSet changes;
        EXPECT_TRUE(changes.setProperty(scene, {K::Object, 4}, "translation", to));
        EXPECT_TRUE(changes.apply(scene));
        if (alsoPlain) (*plain)->applyCoarse(scene, changes);
        return (*preview)->applyCoarse(scene, changes);
    };
    EXPECT_NE(frame(glm::vec3(0.2f, 0.5f, 0.0f), true).method, "shadowField"); // the build starts
    ASSERT_TRUE((*preview)->waitForFieldDrag(kBox));
    for (const glm::vec3& to : {glm::vec3(0.25f, 0.5f, 0.05f), glm::vec3(0.35f, 0.5f, 0.1f)}) {
        const EditSummary summary = frame(to, true);
        EXPECT_EQ(summary.method, "shadowField");
        EXPECT_GT(summary.statesCarried, 0u);
        EXPECT_TRUE((*preview)->finePending());
        EXPECT_EQ(util::maxRelativeDifference((*preview)->firstAnswer(w, h), (*preview)->fine().image(w, h)), 0.0);
    }
    auto scratch = RelightPreview::create(scene, settings);
    ASSERT_TRUE(scratch);
    const double fieldError = relativeRmse((*preview)->firstAnswer(w, h), (*scratch)->image());
    const double coarseError = relativeRmse((*plain)->firstAnswer(w, h), (*scratch)->image());
    std::printf("relRMSE vs the exact preview after 3 frames: field drag %.4f, coarse first answer %.4f\n",
                fieldError, coarseError);
    EXPECT_GT(fieldError, 0.0); // approximate
    EXPECT_LT(fieldError, 0.5 * coarseError);

    auto expectExact = [&] {
        EXPECT_FALSE((*preview)->finePending());
        auto fine = RelightPreview::create(scene, settings);
        auto coarse = RelightPreview::create(scene, (*preview)->coarse().settings());
        ASSERT_TRUE(fine && coarse);
        EXPECT_LE(util::maxRelativeDifference((*preview)->firstAnswer(w, h), (*fine)->image()), 1e-6);
        EXPECT_LE(util::maxRelativeDifference((*preview)->coarseImage(w, h), (*coarse)->image(w, h)), 1e-6);
    };
    const EditSummary settled = (*preview)->applyFine();
    EXPECT_EQ(settled.method, "shadowField settled");
    EXPECT_GT(settled.pointsTouched, 0u);
    ASSERT_NO_FATAL_FAILURE(expectExact());

    // A second drag: the caches rebuilt for it (the field kept), then a roughness edit mid-drag.
    EXPECT_NE(frame(glm::vec3(0.4f, 0.5f, 0.1f), false).method, "shadowField");
    ASSERT_TRUE((*preview)->waitForFieldDrag(kBox));
    EXPECT_EQ(frame(glm::vec3(0.45f, 0.5f, 0.1f), false).method, "shadowField");
    scene::ChangeSet rough;
    ASSERT_TRUE(rough.setProperty(scene, {K::Material, 2}, "roughness", 0.5f));
    ASSERT_TRUE(rough.apply(scene));
    EXPECT_NE((*preview)->applyCoarse(scene, rough).method, "shadowField");
    EXPECT_TRUE((*preview)->finePending());
    EXPECT_NE((*preview)->applyFine().method, "shadowField settled");
    ASSERT_NO_FATAL_FAILURE(expectExact());
    EXPECT_NE((*preview)->fine().shadowField(), nullptr); // translated the exact way: kept

    // Prepared before the drag (the editor: on selection), the first frame takes the field; a
    // build that applyFine meets is cancelled and dropped (the next one starts afresh).
    EXPECT_FALSE((*preview)->fine().fieldDragReady(kBox)); // the caches went with the settle
    ASSERT_TRUE((*preview)->prepareFieldDrag(kBox));
    EXPECT_FALSE((*preview)->prepareFieldDrag(kBox)); // one at a time
    scene::ChangeSet light; // a light move, applied at once (the editor's exact edits)
    ASSERT_TRUE(light.setProperty(scene, {K::Light, 7}, "position", glm::vec3(-1.0f, 2.2f, 0.3f)));
    ASSERT_TRUE(light.apply(scene));
    (*preview)->applyCoarse(scene, light);
    EXPECT_EQ((*preview)->applyFine().kind, "light"); // the build cancelled first
    EXPECT_FALSE((*preview)->fine().fieldDragReady(kBox));
    ASSERT_NO_FATAL_FAILURE(expectExact());
    ASSERT_TRUE((*preview)->prepareFieldDrag(kBox));
    ASSERT_TRUE((*preview)->waitForFieldDrag(kBox));
    EXPECT_FALSE((*preview)->prepareFieldDrag(kBox)); // ready already
    EXPECT_EQ(frame(glm::vec3(0.5f, 0.5f, 0.1f), false).method, "shadowField");
    (*preview)->applyFine();
    ASSERT_NO_FATAL_FAILURE(expectExact());

    // A build still running when the preview goes: the destructor cancels it and waits.
    frame(glm::vec3(0.55f, 0.5f, 0.1f), false);
    preview->reset();
}

// A field outlives its preview (a camera move rebuilds the editor's): offered to a new preview of
// the same object it is taken as it is (the same field, not a copy), unless the object's rotation
// changed since.
TEST(RelightCoarseToFine, OfferedFieldIsTakenWhileTheObjectOnlyTranslated) {
    scene::Scene scene = testing::makeRelightScene();
    const RelightSettings settings = testing::smallSettings();
    constexpr size_t kBox = 1;
    ShadowFieldSettings field;
    field.reuseOwnStates = true;
    auto first = CoarseToFinePreview::create(scene, settings, -1, 2, true);
    ASSERT_TRUE(first);
    EXPECT_FALSE((*first)->keptField());
    (*first)->enableFieldDrags(field);
    ASSERT_TRUE((*first)->prepareFieldDrag(kBox));
    ASSERT_TRUE((*first)->waitForFieldDrag(kBox));
    const auto kept = (*first)->keptField();
    ASSERT_TRUE(kept && kept->field);
    EXPECT_EQ(kept->object, scene.objects[kBox].id);

    auto offeredTo = [&](const scene::Scene& s) -> const ShadowField* {
        auto next = CoarseToFinePreview::create(s, settings, -1, 2, true);
        if (!next) return nullptr;
        (*next)->enableFieldDrags(field);
        (*next)->offerField(*kept);
        EXPECT_TRUE((*next)->prepareFieldDrag(kBox));
        EXPECT_TRUE((*next)->waitForFieldDrag(kBox));
        return (*next)->fine().shadowField() == kept->field.get() ? kept->field.get() : nullptr;
    };
    scene::Scene moved = scene; // another camera and a translation: the same field
    moved.camera.position = {0.5f, 2.0f, 5.5f};
    moved.objects[kBox].transform.translation += glm::vec3(0.2f, 0.0f, 0.1f);
    EXPECT_EQ(offeredTo(moved), kept->field.get());
    scene::Scene rotated = scene; // a rotation: a field of its own
    rotated.objects[kBox].transform.rotationDeg = {0.0f, 30.0f, 0.0f};
    EXPECT_EQ(offeredTo(rotated), nullptr);
}

} // namespace
} // namespace wavelit::relight
