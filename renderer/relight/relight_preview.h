// RelightPreview: the instant relighting preview of architecture.md §5.A for one scene and camera
// (docs/relighting.md). create() computes every preview point's factors and cached products from
// scratch; applyChanges() takes the scene after an edit and the edit's scene::ChangeSet and
// rebuilds only the factor the change set invalidates, only where it can matter:
//   environment rotation                      L once, then 4 pi <T_K, L> per point;
//   environment intensity / tint              nothing: terms are cached per unit power;
//   light k position, size, shape ...         <T, L_k> per point (lighting is linear);
//   light k intensity / colour                nothing: terms are cached per unit power;
//   material m                                f, hence T and every term, on m's points;
//   object j moved / re-shaped                j's BVH and bounds; the G-buffer re-cast: points
//                                             whose hit changed are rebuilt whole, the others
//                                             re-cast O_j only where j's old or new bounding
//                                             cone meets their lit texels;
//   object j's material                       T on the points whose material changed;
//   camera                                    every point (the G-buffer changes everywhere).
// Display-only edits (exposure) and render settings rebuild nothing. An edit that adds or removes
// entities rebuilds everything. The result equals create() on the edited scene bit for bit (per
// point the same inputs go through the same code; tests check ≤ 1e-6 relative per edit kind).
// One owner thread; the per-point work runs on `threads` workers inside each call.
#pragma once

#include "relight/drag_cache.h"
#include "relight/environment_factor.h"
#include "relight/object_occluder.h"
#include "relight/point_transfer.h"
#include "relight/preview_points.h"
#include "relight/shadow_field.h"
#include "relight/texel_directions.h"
#include "scene/bvh.h"
#include "scene/change_set.h"
#include "scene/scene.h"
#include "util/image.h"
#include "util/result.h"

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace wavelit::relight {

struct RelightSettings {
    int width = 128;   // preview points: the G-buffer's resolution
    int height = 128;
    int level = 5;     // sphere grid 2^level squared (5: 32^2, architecture.md §5.A)
    size_t keep = 128; // K: Haar coefficients of T kept per point
    int threads = 2;
};

struct EditSummary {
    std::string kind; // environment, light, material, object, camera, display, structure
    std::vector<std::string> factorsRebuilt;
    size_t pointsTouched = 0; // preview points with any per-point work
    double sharedMs = 0.0;    // shared factors: environment, object BVHs, G-buffer (reports only)
    double pointsMs = 0.0;    // the per-point work
    // A translation drag through the object's shadow field (enableShadowField): "shadowField",
    // else empty (the exact path). Its points whose camera hit moved onto the object were rebuilt
    // exactly (`pointsRebuilt`, with rays); `fieldFallbacks` points lay beyond the field's outer
    // shell (j's cone ray-cast); `cacheMs`: drag caches rebuilt first (after another edit).
    std::string method;
    size_t pointsRebuilt = 0;
    size_t fieldFallbacks = 0;
    // Of the rebuilt points on a non-convex moved object: those whose self-visibility came from
    // the drag start's own-surface cache (the nearest cached point's mask) instead of rays.
    size_t selfMasksReused = 0;
    // With ShadowFieldSettings::reuseOwnStates: the moved object's points whose visibility was
    // carried from the drag start's nearest point of it (no rays, no T; not in pointsRebuilt).
    size_t statesCarried = 0;
    double cacheMs = 0.0;
    double rebuiltCpuMs = 0.0; // time of the points whose camera hit changed, summed over workers
};

// What enableShadowField built: the field (time, bytes) and the per-point drag caches.
struct ShadowFieldInfo {
    double fieldMs = 0.0;
    size_t fieldBytes = 0;
    double cacheMs = 0.0;
    size_t cachedPoints = 0;
    size_t cacheBytes = 0;
};

class RelightPreview {
    struct FieldDrag; // the shadow-field drag's state (below)

public:
    // Invalid error when the settings are out of range (level 1..7, size 1..4096, keep >= 1).
    static util::Result<std::unique_ptr<RelightPreview>> create(const scene::Scene& scene,
                                                                const RelightSettings& settings);

    // `edited` is the scene after `changes` was applied to this preview's scene.
    // deferMovedObjects (the coarse preview of a drag, first_answer.h): points whose camera ray now
    // meets an object this edit moves keep their old point and state — their image is stale, the
    // rest exact — and are listed by deferred(); the next edit without it (an empty change set
    // will do) rebuilds them from scratch first, so the preview equals create() again after it.
    // useField false: a translation of the field's object takes the exact path too (the field
    // is kept; the caller wants the exact state at once, CoarseToFinePreview::applyFine).
    EditSummary applyChanges(const scene::Scene& edited, const scene::ChangeSet& changes,
                             bool deferMovedObjects = false, bool useField = true);
    const std::vector<uint8_t>& deferred() const { return m_deferred; }

    // Translation drags of `object` through its shadow field (docs/relighting.md §7.0e): builds the
    // field and every other hit point's drag cache (drag_cache.h). While only that object's
    // translation changes, applyChanges updates the terms from the field — approximate (the
    // field's position sampling), no visibility rays but for the points the object now covers —
    // and summary.method says "shadowField"; the first other edit first restores the exact state
    // (the points the field updated re-cast O_j and rebuild T: equal to create() again), and
    // drops the caches (rebuilt at the next translation); a rotation, scale or mesh edit of the
    // object, or a structural one, drops the field (its masks live in world axes). With
    // settings.reuseOwnStates the object's own points rebuilt by the drag carry their visibility
    // from the drag start's nearest point of it instead (carriedVisibilityState: no rays, no T;
    // summary.statesCarried), and the first other edit rebuilds them whole (§7.0j).
    ShadowFieldInfo enableShadowField(size_t object, const ShadowFieldSettings& settings = {});
    // enableShadowField in two halves, for a caller that builds off its own thread (the editor's
    // drags, coarse_to_fine.h): prepareShadowField only reads this preview (concurrent const
    // calls are safe; no edit may run meanwhile) and returns the field and the drag caches of
    // the state it read — reusing this preview's field of the object when the settings match
    // (its masks stay valid while the object only translates); installShadowField takes them
    // when no edit came in between (else false: prepare again). Nothing is prepared (an invalid
    // result) while some point's terms come from a field, nor when `cancel` (if given) is set
    // before it is done (checked per field sample and per point: it ends within a block of them).
    struct PreparedShadowField {
        ShadowFieldInfo info;
        bool valid() const { return drag != nullptr; }

    private:
        friend class RelightPreview;
        std::unique_ptr<FieldDrag> drag;
        uint64_t revision = 0;
    };
    // `reuse`: a field of this object built by another preview (the caller vouches that the
    // object's mesh, rotation and scale are the same), taken when its settings match.
    PreparedShadowField prepareShadowField(size_t object, const ShadowFieldSettings& settings = {},
                                           const std::atomic<bool>* cancel = nullptr,
                                           std::shared_ptr<const ShadowField> reuse = nullptr) const;
    bool installShadowField(PreparedShadowField&& prepared);
    // Whether a translation of `object` would be a field drag now without building anything
    // first (its field installed, the drag caches built).
    bool fieldDragReady(size_t object) const;
    // Whether applyChanges(edited, changes) would take the field: only translations of its object.
    bool isFieldDrag(const scene::Scene& edited, const scene::ChangeSet& changes) const;
    bool fieldApproximate() const; // some point's terms come from the field
    size_t approximatePoints() const; // how many
    // Per point: whether the last applyChanges did any work on it.
    const std::vector<uint8_t>& lastTouched() const { return m_touched; }
    const ShadowField* shadowField() const { return m_field ? m_field->field.get() : nullptr; }
    // The installed field and its object (null: none), for a later preview of the same scene
    // (prepareShadowField's `reuse`).
    std::shared_ptr<const ShadowField> shadowFieldShared() const { return m_field ? m_field->field : nullptr; }
    std::optional<size_t> shadowFieldObject() const {
        return m_field ? std::optional<size_t>(m_field->object) : std::nullopt;
    }
    const std::vector<PointDragCache>* dragCaches() const { return m_field ? &m_field->caches : nullptr; }
    const std::vector<glm::vec3>& fieldEnvTexels() const; // L(t) dOmega per texel (tests)

    // The first answer of a material edit (docs/relighting.md §7.0g) without applying it: the
    // image after `changes`, `edited` being this preview's scene after them, when they edit
    // materials only (BRDF parameters, the BRDF, colour, emission). On the points whose T the
    // edit invalidates (applyChanges would rebuild them) the terms come from untruncatedTerms
    // (point_transfer.h) — the cached visibility, the new f, the full-resolution L: the texel sum
    // that equals the full preview at every Haar coefficient, with no transform and no top K;
    // elsewhere from the cached terms with the edited colours and emissions. So it differs from
    // the full answer (applyChanges, then image()) by T's truncation to K coefficients only.
    // The preview is unchanged. nullopt when the change set holds anything else, or some point is
    // deferred or taken from a shadow field. A material it recomputes whose lobe is narrower than
    // a texel (ResolvedMaterial::narrow) has f averaged over the texels near the mirror direction:
    // over kSub^2 directions each with LobeAverage::Full, as the full answer (2-4x a wide lobe's
    // cost, over the frame budget, §7.0g); over kCoarseSub^2 with Coarse, what the editor shows
    // (a quarter of the BRDF evaluations; within relRMSE 0.05 of the full answer on the bundled
    // gold, §7.0h), flagged coarseLobes, and only while the edited materials' points times the
    // grid's texels stay within kCoarseLobeTexelBudget (else nullopt: the walk alone would miss
    // the frame).
    static constexpr double kCoarseLobeTexelBudget = 16.0 * 1024 * 1024;
    struct MaterialFirstAnswer {
        util::ImageRGB image; // at preview resolution
        size_t pointsTouched = 0;
        std::vector<std::string> materials; // whose points were recomputed
        bool coarseLobes = false; // some recomputed lobe was narrow and averaged coarsely
    };
    std::optional<MaterialFirstAnswer>
    materialFirstAnswer(const scene::Scene& edited, const scene::ChangeSet& changes,
                        LobeAverage narrowLobes = LobeAverage::Full) const;

    // Linear radiance at preview resolution, and scaled to width x height (nearest point).
    util::ImageRGB image() const;
    util::ImageRGB image(int width, int height) const;

    const RelightSettings& settings() const { return m_settings; }
    const scene::Scene& scene() const { return *m_scene; }
    const std::vector<PreviewPoint>& points() const { return m_points; }
    const std::vector<PointState>& states() const { return m_states; }
    const scene::Bvh& bvh() const { return m_bvh; } // every object of scene()
    TransferContext context() const;
    size_t hitCount() const;
    size_t stateBytes() const; // sum of PointState::bytes over hit points

private:
    explicit RelightPreview(const RelightSettings& settings);
    void rebuildAll(const scene::Scene& scene);
    void resolveMaterials(); // and m_unitLights
    glm::vec3 radiance(size_t i, const std::vector<glm::vec3>& lightPowers) const;

    RelightSettings m_settings;
    TexelDirections m_dirs;
    std::unique_ptr<scene::Scene> m_scene;
    scene::Bvh m_bvh;
    std::vector<ObjectOccluder> m_occluders;
    ConvexityCache m_convexity; // per mesh, kept across edits
    std::vector<ResolvedMaterial> m_materials;
    EnvironmentFactor m_environment;
    std::shared_ptr<const util::ImageRGB> m_envSource; // reduceEquirect of the environment's image
    const util::ImageRGB* m_envSourceOf = nullptr;     // the image it was reduced from
    void buildEnvironment();
    std::vector<PreviewPoint> m_points;
    std::vector<PointState> m_states; // empty state for a miss
    std::vector<uint8_t> m_deferred;   // per point: stale (applyChanges' deferMovedObjects)
    std::vector<glm::vec3> m_background; // environment seen by missed rays
    // Per light, per pixel: the light seen directly by the camera, per unit power.
    std::vector<std::vector<glm::vec3>> m_cameraLights;
    std::vector<scene::Light> m_unitLights; // unitPowerLight of each light
    void updateCameraLight(size_t k, size_t pixel, const CameraRays& rays);
    // Preview points re-cast where the camera ray meets one of the spheres (the rest copied).
    std::vector<PreviewPoint> recastNear(const std::vector<BoundingSphere>& spheres) const;
    std::vector<uint8_t> m_touched;

    // The shadow-field drag (field_drag.cpp).
    struct FieldDrag {
        size_t object = 0;
        std::shared_ptr<const ShadowField> field; // shared with preparations that reuse it
        scene::Bvh bvhWithout;              // every object but `object`
        std::vector<glm::vec3> envTexels;   // L(t) x dOmega
        std::vector<PointDragCache> caches; // per point; invalid for misses and the object's own
        bool cachesValid = false;
        std::vector<uint8_t> approximate;   // per point: terms from the field (O_j and T stale)
        // The object's own surface points at the drag's start, in its frame (offset from its
        // bounding centre then), with the texels the object blocks for them (above & ~lit):
        // self-visibility is translation-invariant, so a point the drag brings into view takes
        // the nearest one's instead of its rays (non-convex objects only; an approximation); with
        // reuseOwnStates also the other objects' occlusion of each (convex objects too).
        glm::vec3 centre{0.0f};
        float cell = 1.0f;
        std::vector<glm::vec3> ownOffset, ownNormal;
        std::vector<TexelBits> ownSelf;                    // non-convex objects only
        std::vector<std::vector<Occlusion>> ownOcclusions; // by the other objects (reuseOwnStates)
        std::unordered_map<int64_t, std::vector<uint32_t>> ownGrid;
        // The nearest cached own point on the same side, or -1.
        int64_t nearestOwn(const glm::vec3& offset, const glm::vec3& normal) const;
    };
    std::unique_ptr<FieldDrag> m_field;
    uint64_t m_revision = 0; // counts applyChanges calls: what a prepared field was built from
    EditSummary applyFieldDrag(const scene::Scene& edited);
    // From the current points and states; `cancel` set: ends early, the caches incomplete.
    void buildDragCaches(FieldDrag& f, const std::atomic<bool>* cancel = nullptr) const;
    // Before any other edit: the exact state back; `dropField` also forgets the field.
    void settleFieldDrag(bool dropField);
};

} // namespace wavelit::relight
