#include "relight/coarse_to_fine.h"

#include "util/timer.h"

#include <algorithm>

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

EditSummary CoarseToFinePreview::applyCoarse(const scene::Scene& edited, const scene::ChangeSet& changes) {
    scene::ChangeSet merged = m_pending ? m_pending->changes : scene::ChangeSet{};
    merged.merge(changes);
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
        if (m_coarseBehind) m_coarseBehind->merge(changes);
        else m_coarseBehind = changes;
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
    if (!m_pending) {
        EditSummary none;
        none.kind = "display";
        return none;
    }
    Pending pending = std::move(*m_pending);
    m_pending.reset();
    const EditSummary summary = m_fine->applyChanges(*pending.scene, pending.changes);
    // Rebuilds deferred points, with the material edits the coarse preview is behind by.
    if (m_coarseBehind) m_coarse->applyChanges(*pending.scene, *m_coarseBehind);
    else m_coarse->applyChanges(m_coarse->scene(), scene::ChangeSet{});
    m_coarseBehind.reset();
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
