#include "relight/coarse_to_fine.h"

#include "relight/edit_rules.h"

#include "util/timer.h"

#include <algorithm>
#include <chrono>

namespace wavelit::relight {

RelightSettings CoarseToFinePreview::coarseSettings(const RelightSettings& settings, int coarseLevel,
                                                   int pointStride) {
    RelightSettings coarse = settings;
    coarse.level = coarseLevel < 0 ? std::max(1, settings.level - 2) : coarseLevel;
    coarse.keep = std::min(settings.keep, size_t(1) << (2 * std::clamp(coarse.level, 1, 7)));
    const int stride = std::max(1, pointStride);
    coarse.width = (settings.width + stride - 1) / stride;
    coarse.height = (settings.height + stride - 1) / stride;
    return coarse;
}

util::Result<std::unique_ptr<CoarseToFinePreview>> CoarseToFinePreview::create(const scene::Scene& scene,
                                                                               const RelightSettings& settings,
                                                                               int coarseLevel, int pointStride,
                                                                               bool deferMovedObjects) {
    auto fine = RelightPreview::create(scene, settings);
    if (!fine) return fine.error();
    auto coarse = RelightPreview::create(scene, coarseSettings(settings, coarseLevel, pointStride));
    if (!coarse) return coarse.error();
    std::unique_ptr<CoarseToFinePreview> out(new CoarseToFinePreview());
    out->m_fine = std::move(fine).value();
    out->m_coarse = std::move(coarse).value();
    out->m_deferMovedObjects = deferMovedObjects;
    out->snapshot();
    return out;
}

CoarseToFinePreview::~CoarseToFinePreview() { collectFieldBuild(Collect::Cancel); }

void CoarseToFinePreview::holdBackFromCoarse(const scene::ChangeSet& changes) {
    if (m_coarseBehind) m_coarseBehind->merge(changes);
    else m_coarseBehind = changes;
}

void CoarseToFinePreview::collectFieldBuild(Collect how) {
    if (!m_fieldBuild.valid()) return;
    if (how == Collect::Poll && m_fieldBuild.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    if (how == Collect::Cancel) m_cancelBuild.store(true);
    // Refused (dropped) when cancelled, or when the full preview changed since the build read it.
    m_fine->installShadowField(m_fieldBuild.get());
}

std::optional<CoarseToFinePreview::KeptField> CoarseToFinePreview::keptField() const {
    const std::optional<size_t> object = m_fine->shadowFieldObject();
    if (!object) return std::nullopt;
    const scene::Object& o = m_fine->scene().objects[*object];
    return KeptField{o.id, o.mesh, o.transform.rotationDeg, o.transform.scale, m_fine->shadowFieldShared()};
}

void CoarseToFinePreview::startFieldBuild(size_t object) {
    std::shared_ptr<const ShadowField> reuse;
    const scene::Object& o = m_fine->scene().objects[object];
    if (m_offered && m_offered->object == o.id && m_offered->mesh == o.mesh &&
        m_offered->rotationDeg == o.transform.rotationDeg && m_offered->scale == o.transform.scale)
        reuse = m_offered->field;
    m_cancelBuild.store(false);
    m_fieldBuild = std::async(std::launch::async, [fine = m_fine.get(), object, settings = *m_fieldSettings,
                                                   cancel = &m_cancelBuild, reuse = std::move(reuse)] {
        return fine->prepareShadowField(object, settings, cancel, reuse);
    });
}

bool CoarseToFinePreview::prepareFieldDrag(size_t object) {
    collectFieldBuild(Collect::Poll);
    if (!m_fieldSettings || m_fieldBuild.valid() || m_pending || m_fieldAhead ||
        object >= m_fine->scene().objects.size() || m_fine->fieldDragReady(object))
        return false;
    startFieldBuild(object);
    return true;
}

bool CoarseToFinePreview::fieldDragReady(size_t object) {
    collectFieldBuild(Collect::Poll);
    return m_fine->fieldDragReady(object);
}

bool CoarseToFinePreview::waitForFieldDrag(size_t object) {
    collectFieldBuild(Collect::Wait);
    return m_fine->fieldDragReady(object);
}

EditSummary CoarseToFinePreview::applyCoarse(const scene::Scene& edited, const scene::ChangeSet& changes) {
    scene::ChangeSet merged = m_pending ? m_pending->changes : scene::ChangeSet{};
    merged.merge(changes);
    collectFieldBuild(Collect::Poll);
    // The object every edit since the full preview's state translates, if one (a drag's frames).
    std::optional<size_t> moved;
    if (const auto id = onlyTranslatedObject(merged);
        m_fieldSettings && id && edited.objects.size() == m_fine->scene().objects.size())
        if (const size_t j = indexOf(edited.objects, *id); j < edited.objects.size()) moved = j;
    if (moved && !m_fieldBuild.valid() && m_fine->fieldDragReady(*moved)) {
        // Every edit since the full preview's state translates the field's object: the full
        // preview takes them through the field; the coarse one gets them with applyFine.
        EditSummary summary = m_fine->applyChanges(edited, merged);
        holdBackFromCoarse(changes);
        m_pending.reset();
        m_material.reset();
        m_fieldAhead = true;
        return summary;
    }
    if (moved && !m_fieldBuild.valid() && !m_fieldAhead) startFieldBuild(*moved); // from the full preview as it is
    // Only material edits since the full preview's state: its visibility stands, so the first
    // answer is its untruncated material answer; the coarse preview takes these edits later.
    util::Timer timer;
    // A narrow lobe averaged over 2 x 2 directions a texel instead of 4 x 4: the answer within the
    // frame budget (docs/relighting.md §7.0h).
    auto material = m_fine->materialFirstAnswer(edited, merged, LobeAverage::Coarse);
    EditSummary summary;
    if (material) {
        summary.kind = "material";
        summary.method = material->coarseLobes ? kUntruncatedCoarseLobes : "untruncated";
        for (const std::string& name : material->materials) summary.factorsRebuilt.push_back("brdf first answer:" + name);
        summary.pointsTouched = material->pointsTouched;
        summary.pointsMs = timer.milliseconds();
        m_material = std::move(material->image);
        holdBackFromCoarse(changes);
    } else {
        m_material.reset();
        scene::ChangeSet coarse = changes;
        if (m_coarseBehind) { // the material edits it has not had, with this one
            coarse = std::move(*m_coarseBehind);
            coarse.merge(changes);
            m_coarseBehind.reset();
        }
        summary = m_coarse->applyChanges(edited, coarse, m_deferMovedObjects);
        for (const scene::Invalidation& inv : changes.invalidations())
            if (inv.factor == scene::FactorKind::Environment || inv.factor == scene::FactorKind::Light ||
                inv.factor == scene::FactorKind::Camera)
                m_correctable = false;
    }
    if (m_pending) {
        m_pending->changes = std::move(merged);
        *m_pending->scene = edited;
    } else {
        m_pending = Pending{std::make_unique<scene::Scene>(edited), changes};
    }
    return summary;
}

EditSummary CoarseToFinePreview::applyFine() {
    if (!m_pending && !m_fieldAhead) {
        EditSummary none;
        none.kind = "display";
        return none;
    }
    collectFieldBuild(Collect::Cancel); // it reads the full preview, which changes now
    EditSummary summary;
    if (m_pending) { // exact: a field drag's points settle first (RelightPreview::applyChanges)
        Pending pending = std::move(*m_pending);
        m_pending.reset();
        summary = m_fine->applyChanges(*pending.scene, pending.changes, false, /*useField=*/false);
    } else { // only field-drag frames since the exact state: their points rebuilt exactly
        const size_t approximate = m_fine->approximatePoints();
        summary = m_fine->applyChanges(m_fine->scene(), scene::ChangeSet{});
        summary.kind = "object";
        summary.method = "shadowField settled";
        summary.pointsTouched = approximate;
    }
    // Rebuilds deferred points, with the edits the coarse preview is behind by (material first
    // answers, field-drag frames).
    if (m_coarseBehind) m_coarse->applyChanges(m_fine->scene(), *m_coarseBehind);
    else m_coarse->applyChanges(m_coarse->scene(), scene::ChangeSet{});
    m_coarseBehind.reset();
    m_fieldAhead = false;
    snapshot();
    return summary;
}

void CoarseToFinePreview::snapshot() {
    m_base = firstAnswerBase(*m_fine, *m_coarse);
    m_correctable = true;
    m_material.reset();
}

util::ImageRGB CoarseToFinePreview::firstAnswer(int width, int height) const {
    if (!m_pending) return m_fine->image(width, height);
    if (m_material) return nearestScaled(*m_material, width, height);
    if (!m_correctable) return m_coarse->image(width, height);
    return correctedFirstAnswer(m_base, *m_coarse, width, height);
}

size_t CoarseToFinePreview::extraBytes() const {
    auto imageBytes = [](const util::ImageRGB& image) { return image.pixels.size() * sizeof(glm::vec3); };
    const size_t pointBytes = sizeof(PreviewPoint);
    return m_coarse->stateBytes() + m_coarse->points().size() * pointBytes + imageBytes(m_base.fine) +
           imageBytes(m_base.coarse) + (m_base.finePoints.size() + m_base.coarsePoints.size()) * pointBytes +
           m_base.objects.size() * sizeof(glm::mat4) + (m_material ? imageBytes(*m_material) : 0);
}

util::ImageRGB CoarseToFinePreview::image(int width, int height) const {
    if (m_pending && m_material) return nearestScaled(*m_material, width, height);
    return m_pending ? m_coarse->image(width, height) : m_fine->image(width, height);
}

} // namespace wavelit::relight
