// RelightPreview::materialFirstAnswer (relight_preview.h; docs/relighting.md §7.0g): a material
// edit's image without rebuilding T. A roughness drag's full update pays, per point of the
// material, for f at every visible texel, then the Haar transform and the top K of T (two T's for
// an affine BRDF: about half of it, §7.0f); the image needs neither — the environment term is an
// inner product, and by Parseval at full resolution the texel sum of T x L equals it with every
// coefficient kept. So the first answer sums f x cosine x visibility x L(t) dOmega over the visible
// texels directly; the full answer (applyChanges) still rebuilds T, so that the next environment
// or light edit stays a K-term update.
#include "relight/relight_preview.h"

#include "relight/edit_rules.h"
#include "relight/light_projection.h"
#include "relight/texel_values.h"
#include "util/parallel_for.h"

#include <algorithm>
#include <string_view>

namespace wavelit::relight {

std::optional<RelightPreview::MaterialFirstAnswer> RelightPreview::materialFirstAnswer(
    const scene::Scene& edited, const scene::ChangeSet& changes, LobeAverage narrowLobes) const {
    // Material property edits only, on the same entities: every point's hit and visibility stand.
    if (changes.edits().empty() || edited.objects.size() != m_scene->objects.size() ||
        edited.materials.size() != m_scene->materials.size() ||
        edited.lighting.lights.size() != m_scene->lighting.lights.size())
        return std::nullopt;
    for (const scene::Edit& e : changes.edits()) {
        const auto* edit = std::get_if<scene::PropertyEdit>(&e);
        if (!edit || edit->entity.kind != scene::EntityKind::Material) return std::nullopt;
    }
    if (std::find(m_deferred.begin(), m_deferred.end(), uint8_t(1)) != m_deferred.end() || fieldApproximate())
        return std::nullopt;

    // The materials whose T the edit invalidates: as applyChanges decides (colour and emission
    // edits of a colour-linear or -affine BRDF are mixed in by the image, no per-point work).
    MaterialFirstAnswer answer;
    std::vector<uint8_t> recompute(m_materials.size(), 0);
    for (const scene::Invalidation& inv : changes.invalidations()) {
        if (inv.factor != scene::FactorKind::MaterialBrdf) continue;
        const size_t m = indexOf(edited.materials, inv.id);
        if (m >= edited.materials.size() || recompute[m]) continue;
        const scene::EntityRef ref{scene::EntityKind::Material, inv.id};
        if (onlyScales(changes, ref, {"emission"})) continue;
        if (m_materials[m].colourUse != ColourUse::Fixed && onlyScales(changes, ref, {"baseColor", "emission"}))
            continue;
        recompute[m] = 1;
        answer.materials.push_back(edited.materials[m].name);
    }

    std::vector<ResolvedMaterial> materials;
    for (const scene::Material& m : edited.materials) materials.push_back(resolveMaterial(m, m_dirs.texelRadius()));
    materials.push_back(m_materials.back()); // the default material
    for (size_t m = 0; m < edited.materials.size(); ++m)
        answer.coarseLobes |=
            narrowLobes == LobeAverage::Coarse && recompute[m] && materials[m].narrow;
    if (answer.coarseLobes) {
        // The walk is ~points x grid texels: past the budget (a 64^2 grid's chrome, ~8x the
        // bundled gold's 32^2) even the coarse average misses the frame, and the corrected
        // coarse answer is the first answer instead (nullopt).
        size_t points = 0;
        for (const PreviewPoint& p : m_points)
            points += p.hit && p.material < recompute.size() && recompute[p.material];
        if (double(points) * double(m_dirs.count()) > kCoarseLobeTexelBudget) return std::nullopt;
    }
    TransferContext ctx = context();
    ctx.scene = &edited; // the same geometry and lights; its materials
    ctx.materials = &materials;
    const std::vector<glm::vec3> envTexels =
        std::any_of(recompute.begin(), recompute.end(), [](uint8_t r) { return r != 0; })
            ? envTexelValues(m_environment, m_dirs)
            : std::vector<glm::vec3>{};
    std::vector<glm::vec3> powers;
    for (const scene::Light& light : edited.lighting.lights) powers.push_back(lightPower(light));
    const glm::vec3 envScale = environmentScale(edited.lighting.environment);

    answer.image = util::ImageRGB(m_settings.width, m_settings.height);
    std::vector<uint8_t> touched(m_points.size(), 0);
    util::parallelFor(m_points.size(), m_settings.threads, [&](size_t i) {
        const PreviewPoint& p = m_points[i];
        glm::vec3 lights(0.0f); // radiance()'s sums, in its order
        for (size_t k = 0; k < m_cameraLights.size(); ++k) lights += m_cameraLights[k][i] * powers[k];
        if (!p.hit) {
            answer.image.pixels[i] = m_background[i] * envScale + lights;
            return;
        }
        const size_t mi = std::min<size_t>(p.material, materials.size() - 1);
        const ResolvedMaterial& m = materials[mi];
        if (mi < recompute.size() && recompute[mi]) {
            thread_local PointTerms terms;
            untruncatedTerms(ctx, p, m_states[i], envTexels, terms, narrowLobes);
            answer.image.pixels[i] = lights + m.emission + mixTerms(m, terms, envScale, powers);
            touched[i] = 1;
        } else {
            answer.image.pixels[i] = lights + m.emission + mixTerms(m, m_states[i], envScale, powers);
        }
    });
    answer.pointsTouched = size_t(std::count(touched.begin(), touched.end(), uint8_t(1)));
    return answer;
}

} // namespace wavelit::relight
