#include "render/sampling/sampler_tables_cache.h"

#include <string>

namespace wavelit::render {
namespace {

// `next` has every piece of `previous` for the same materials in the same order, under the same
// names (they appear in the report): handing back `previous` itself then tells callers, by
// pointer, that nothing needs re-uploading.
bool samePieces(const DirectionSamplerTables& previous, const DirectionSamplerTables& next) {
    if (previous.kind() != next.kind() || !next.environmentReused() ||
        previous.materialCount() != next.materialCount())
        return false;
    for (size_t i = 0; i < next.materialCount(); ++i) {
        const SamplerMaterial &a = previous.material(i), &b = next.material(i);
        if (a.name != b.name || !sameSampling(a, b) ||
            previous.productTables(i) != next.productTables(i))
            return false;
    }
    return true;
}

} // namespace

std::vector<bool> materialsInUse(const scene::Scene& scene) {
    const size_t defaultIndex = scene.materials.size();
    std::vector<bool> used(defaultIndex + 1, false);
    for (const scene::Object& obj : scene.objects) {
        if (!obj.mesh || obj.mesh->triangleCount() == 0)
            continue;
        // bvh.cpp keeps the last match; ids are unique, so first or last is the same material.
        size_t index = defaultIndex;
        for (size_t i = 0; i < scene.materials.size(); ++i)
            if (scene.materials[i].id == obj.materialId)
                index = i;
        used[index] = true;
    }
    return used;
}

util::Result<std::vector<SceneMaterial>> resolveSceneMaterials(const scene::Scene& scene) {
    std::vector<scene::Material> all = scene.materials;
    all.push_back(scene::Material{}); // the default, as in bvh.cpp and the tracers
    std::vector<SceneMaterial> out;
    for (size_t i = 0; i < all.size(); ++i) {
        const plugins::Brdf* brdf = plugins::findBrdf(all[i].brdf);
        if (!brdf)
            return util::makeError(util::ErrorKind::Unsupported, "",
                                   "material '" + all[i].name + "' uses unknown BRDF '" +
                                       all[i].brdf + "'",
                                   "/materials/" + std::to_string(i) + "/brdf");
        out.push_back({all[i], brdf});
    }
    return out;
}

util::Result<SceneSamplerTables> SamplerTablesCache::update(const scene::Scene& scene,
                                                            SamplerKind kind) {
    auto all = resolveSceneMaterials(scene);
    if (!all)
        return all.error();
    SceneSamplerTables out;
    out.samplerIndexOfMaterial.assign(all->size(), -1);
    if (kind == SamplerKind::Bsdf)
        return out;

    const std::vector<bool> used = materialsInUse(scene);
    std::vector<SamplerMaterial> materials;
    for (size_t i = 0; i < all->size(); ++i)
        if (used[i]) {
            const scene::Material& m = (*all)[i].material;
            out.samplerIndexOfMaterial[i] = int(materials.size());
            materials.push_back({m.name, (*all)[i].brdf, plugins::BrdfParams{m.baseColor, m.roughness}});
        }
    auto tables = DirectionSamplerTables::build(scene.lighting.environment, std::move(materials),
                                                kind, m_previous.get(), m_envOptions);

    ++(tables->environmentReused() ? m_rebuilds.environmentReuses : m_rebuilds.environmentBuilds);
    for (size_t i = 0; i < tables->materialCount(); ++i)
        if (tables->productTables(i))
            ++(tables->productTablesReused(i) ? m_rebuilds.materialReuses
                                              : m_rebuilds.materialBuilds);
    if (!m_previous || !samePieces(*m_previous, *tables))
        m_previous = std::move(tables);
    out.tables = m_previous;
    return out;
}

} // namespace wavelit::render
