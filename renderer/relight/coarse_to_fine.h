// Coarse-to-fine relighting (issue 13): a first answer within a UI frame of an edit from the
// coarse levels of the sphere grid's Haar pyramid, then the full answer. Two previews of the same
// scene and camera: a coarse one on the 2^(n-2) grid (16 x fewer texels: every factor's coarse
// coefficients, hence 16 x fewer occlusion rays and BRDF evaluations per point and a cheaper
// light projection), optionally on every `pointStride`-th pixel per axis (its image upsampled by
// nearest point), and the full one. An edit goes to the coarse preview at once
// (applyCoarse, then coarseImage); the full preview takes the edits that piled up in one merged
// change set when the editor has time (applyFine, then image) — during a drag that is once the
// drag pauses, not once per frame. After applyFine the full image equals RelightPreview::create
// on the edited scene (and the coarse one a coarse create), as each preview alone does.
#pragma once

#include "relight/first_answer.h"
#include "relight/relight_preview.h"

#include <atomic>
#include <future>
#include <memory>
#include <optional>

namespace wavelit::relight {

class CoarseToFinePreview {
public:
    // coarseLevel < 0: settings.level - 2 (at least 1). Keeps min(settings.keep, 4^coarseLevel)
    // coefficients on the coarse grid; pointStride >= 1: the coarse preview has
    // ceil(width / stride) x ceil(height / stride) points. deferMovedObjects: applyCoarse leaves
    // the coarse points on a moved object stale (RelightPreview::applyChanges; firstAnswer takes
    // those pixels from the full image, §7.0c), applyFine rebuilds them; without it the coarse
    // preview equals a coarse build from scratch after every applyCoarse. Errors as
    // RelightPreview::create.
    static util::Result<std::unique_ptr<CoarseToFinePreview>> create(const scene::Scene& scene,
                                                                     const RelightSettings& settings,
                                                                     int coarseLevel = -1,
                                                                     int pointStride = 1,
                                                                     bool deferMovedObjects = false);
    // The coarse preview's settings for these arguments (what create uses).
    static RelightSettings coarseSettings(const RelightSettings& settings, int coarseLevel = -1,
                                          int pointStride = 1);

    // The first answer: `edited` is the scene after `changes`; the full preview is now behind.
    // While every pending edit is a material edit (a roughness slider), the first answer is the
    // full preview's materialFirstAnswer (relight_preview.h, docs/relighting.md §7.0g: the new
    // material's points summed over the texels without T's Haar transform and top K, the rest
    // of the image exact; a lobe narrower than a texel averaged over 2 x 2 directions a texel,
    // §7.0h) and the coarse preview is left behind by those edits until applyFine
    // or the next other edit (which takes them with it); the summary then has kind "material"
    // and method "untruncated" (kUntruncatedCoarseLobes with a narrow lobe). Otherwise the edit
    // goes to the coarse preview.
    //
    // With field drags on (enableFieldDrags), a translation of one object also starts building
    // that object's shadow field and drag caches from the full preview, on a thread of its own
    // (RelightPreview::prepareShadowField: ~0.5 s for a new field at 128^2 on 2 cores, ~0.1 s
    // for the caches alone when the object's field exists); the drag's frames stay the coarse
    // first answer meanwhile. Once it is ready, the next applyCoarse installs it and takes the
    // translations since the full preview's state to the full preview through the field (its
    // summary: method "shadowField"): all-frequency shadows at the full grid, no rays but for
    // the surface the object uncovers, approximate (the field's position sampling) — the full
    // preview's image is then the first answer, the coarse preview takes those edits with the
    // next applyFine, which makes the full preview exact.
    EditSummary applyCoarse(const scene::Scene& edited, const scene::ChangeSet& changes);
    void enableFieldDrags(const ShadowFieldSettings& settings) { m_fieldSettings = settings; }
    // Starts building `object`'s field and caches before any drag (the editor: when the object
    // is selected), so its first drag frame can take the field. Nothing when field drags are
    // off, one is being built, the object's is ready, or the full preview is behind. True when
    // a build started.
    bool prepareFieldDrag(size_t object);
    // Waits for a field being built and installs it if it still fits (tests). True when a field
    // drag of `object` is ready.
    bool waitForFieldDrag(size_t object);
    // The same without waiting: installs a finished build, then says whether `object`'s drag
    // frames would take the field now.
    bool fieldDragReady(size_t object);
    // A shadow field outlives its preview: it depends on the object's mesh, rotation and scale,
    // not on the camera. keptField() is the full preview's field with what it depends on (none:
    // nullopt); offerField() hands one to a later preview (the editor's, rebuilt after a camera
    // move), whose next build of that object takes it instead of building a new one while the
    // object's mesh, rotation and scale are still the same (its caches alone are built).
    struct KeptField {
        scene::EntityId object = scene::kInvalidId;
        std::shared_ptr<const scene::TriangleMesh> mesh;
        glm::vec3 rotationDeg{0.0f}, scale{1.0f};
        std::shared_ptr<const ShadowField> field;
    };
    std::optional<KeptField> keptField() const;
    void offerField(KeptField kept) { m_offered = std::move(kept); }
    static constexpr const char* kUntruncatedCoarseLobes = "untruncated, coarse lobes";
    // Brings the full preview up to the newest edited scene with every pending change set merged
    // into one (an empty summary, kind "display", when nothing is pending). A field still being
    // built is cancelled first (it reads the full preview; it stops within a block of points).
    EditSummary applyFine();
    // Edits the full preview has not had, or has had through a shadow field only.
    bool finePending() const { return m_pending.has_value() || m_fieldAhead; }

    // The full preview's image when nothing is pending, else the coarse one's (the material
    // first answer while that is the first answer: the coarse preview is behind then).
    util::ImageRGB image(int width, int height) const;
    util::ImageRGB coarseImage(int width, int height) const { return m_coarse->image(width, height); }
    // APPROXIMATE first answer while the full one is pending (first_answer.h): the full image of
    // the last applyFine corrected by the coarse preview's change since; the full image when
    // nothing is pending. Much closer to the exact full answer than coarseImage for object and
    // material edits (§7.0c); once an environment, light or camera edit is pending it is
    // coarseImage (there the correction measured worse than the coarse image). While only
    // material edits are pending: the material first answer (applyCoarse).
    util::ImageRGB firstAnswer(int width, int height) const;
    bool materialFirstAnswer() const { return m_material.has_value(); }

    const RelightPreview& fine() const { return *m_fine; }
    const RelightPreview& coarse() const { return *m_coarse; }
    // What coarse-to-fine costs on top of the full preview alone, in bytes: the coarse preview's
    // per-point states and points, and the first answer's snapshot of both images and point sets
    // (FirstAnswerBase). Not counted: the coarse preview's scene copy and BVHs (the size of the
    // full preview's own copies).
    size_t extraBytes() const;

    ~CoarseToFinePreview(); // cancels a field being built and waits for it (it reads the full preview)

private:
    CoarseToFinePreview() = default;
    struct Pending {
        std::unique_ptr<scene::Scene> scene;
        scene::ChangeSet changes;
    };
    std::unique_ptr<RelightPreview> m_fine, m_coarse;
    std::optional<Pending> m_pending;
    // At the full preview's state (create, applyFine): its image and the coarse one's.
    FirstAnswerBase m_base;
    bool m_correctable = true; // no environment, light or camera edit pending
    // The material first answer (preview resolution) while only material edits are pending, and
    // those edits, which the coarse preview has not had yet.
    std::optional<util::ImageRGB> m_material;
    std::optional<scene::ChangeSet> m_coarseBehind;
    void holdBackFromCoarse(const scene::ChangeSet& changes); // merged into m_coarseBehind
    bool m_deferMovedObjects = false;
    void snapshot();
    // Field drags (enableFieldDrags): the settings, the build in flight and its cancel flag, a
    // field offered by an earlier preview, and whether the full preview took edits through the
    // field since its exact state.
    std::optional<ShadowFieldSettings> m_fieldSettings;
    std::future<RelightPreview::PreparedShadowField> m_fieldBuild;
    std::atomic<bool> m_cancelBuild{false};
    std::optional<KeptField> m_offered;
    bool m_fieldAhead = false;
    void startFieldBuild(size_t object);
    // A field being built: Poll installs it into the full preview if it is ready, Wait once it
    // is, Cancel stops it and drops it.
    enum class Collect { Poll, Wait, Cancel };
    void collectFieldBuild(Collect how);
};

} // namespace wavelit::relight
