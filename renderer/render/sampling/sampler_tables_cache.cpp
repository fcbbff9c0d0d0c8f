#include "render/sampling/sampler_tables_cache.h"

#include <algorithm>
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

// Whether any of `changed` can alter a table: the environment, a material's BRDF, which
// material an object uses, or which objects exist (materials in use).
bool touchesTables(const std::vector<scene::Invalidation>& changed) {
    using F = scene::FactorKind;
    return std::any_of(changed.begin(), changed.end(), [](const scene::Invalidation& i) {
        return i.factor == F::Environment || i.factor == F::MaterialBrdf ||
               i.factor == F::ObjectMaterial || i.factor == F::ObjectGeometry;
    });
}

bool touchesEnvironment(const std::vector<scene::Invalidation>& changed) {
    return std::any_of(changed.begin(), changed.end(), [](const scene::Invalidation& i) {
        return i.factor == scene::FactorKind::Environment;
    });
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

util::Result<SceneSamplerTables> SamplerTablesCache::update(
    const scene::Scene& scene, SamplerKind kind, const std::vector<scene::Invalidation>* changed) {
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
            materials.push_back({m.name, (*all)[i].brdf, scene::brdfParamsOf(m)});
        }
    const bool sameKind = m_previous && m_previous->kind() == kind;
    if (changed && sameKind && !touchesTables(*changed)) {
        // A light, camera or display edit: the previous tables are right as they are.
        ++m_rebuilds.environmentReuses;
        for (size_t i = 0; i < m_previous->materialCount(); ++i)
            if (m_previous->productTables(i))
                ++m_rebuilds.materialReuses;
        out.tables = m_previous;
        return out;
    }
    // Keyed by the change set: an unchanged environment is the previous one (the reuse test then
    // matches on the shared image pointer, with no texel comparison); an edited one is compared
    // field by field: one only turned is the previous turned, its product tables kept (all
    // env-local); any other change rebuilds it, and with it every product table (they hold
    // environment factors).
    const DirectionSamplerTables* previous = m_previous.get();
    const scene::Environment* env = &scene.lighting.environment;
    if (changed && sameKind && !touchesEnvironment(*changed))
        env = &m_previous->sourceEnvironment();
    auto tables = DirectionSamplerTables::build(*env, std::move(materials), kind, previous,
                                                m_envOptions);

    ++(tables->environmentReused()    ? m_rebuilds.environmentReuses
       : tables->environmentRotated() ? m_rebuilds.environmentRotations
                                      : m_rebuilds.environmentBuilds);
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
