// SamplerTablesCache: the direction samplers' tables for a scene, kept across edits so each change
// set rebuilds only what it invalidates (issue 6; architecture.md §5 "Edits reach the renderer as change
// sets", §7 "Model only what a scene needs"):
//   environment change (image, tint)                     -> the env tables and every material's
//                                                            product tables (they hold env factors)
//   environment rotation                                 -> the env tables turned, nothing rebuilt
//   environment intensity                                -> nothing (tables built at intensity 1)
//   material edit (BRDF, baseColor, roughness)           -> that material's product tables only
//   object move / mesh change                            -> nothing here (the BVH is the caller's)
//   material added but used by no object                 -> nothing: unused materials get no tables
// With a change set's invalidations (update's `changed`), what to rebuild is read from them: no
// Environment invalidation means the environment is the previous one (never compared texel by
// texel), and invalidations that touch no table (lights, camera) hand back the previous tables
// without building anything. Without them (a whole new scene: open, reload), reuse is decided on
// the inputs (DirectionSamplerTables::build with a previous build).
// One cache per integrator; the tables it returns are immutable and may outlive it.
// Not thread-safe: driven by the thread that owns the integrator.
#pragma once

#include "plugins/brdf.h"
#include "render/sampling/direction_sampler.h"
#include "render/session/render_options.h"
#include "render/sampling/sampler_environment.h"
#include "scene/property_registry.h"
#include "scene/scene.h"
#include "util/result.h"

#include <memory>
#include <vector>

namespace wavelit::render {

// Cumulative counts of pieces built and reused by SamplerTablesCache::update. Material counts
// are of product tables (kind Wavelet only); the other kinds' tables are the env alone.
struct SamplerTablesRebuilds {
    int environmentBuilds = 0;
    int materialBuilds = 0;
    int materialReuses = 0;
    int environmentReuses = 0;
    int environmentRotations = 0; // the previous env tables turned (an env rotation edit)
};

struct SceneSamplerTables {
    std::shared_ptr<const DirectionSamplerTables> tables; // nullptr for SamplerKind::Bsdf
    // One entry per scene material plus one for the default material at the end (bvh.cpp gives
    // objects with an unknown material id the index materials.size()): the material's index in
    // `tables`, or -1 when no object uses it (no tables are built for unused materials) and for
    // every material when `tables` is nullptr.
    std::vector<int> samplerIndexOfMaterial;
};

// Which materials some object's triangles use, resolved as bvh.cpp resolves them: one entry per
// scene material plus the default material at the end (objects whose id matches none).
// Objects without triangles use nothing (they are not in the BVH).
std::vector<bool> materialsInUse(const scene::Scene& scene);

// The scene's materials plus the default material at the end (as materialsInUse), each with its
// BRDF plugin. Errors: a material whose BRDF no plugin implements (Unsupported, naming the
// material, where "/materials/i/brdf"). Shared by the cache and the CPU tracer.
struct SceneMaterial {
    scene::Material material;
    const plugins::Brdf* brdf = nullptr;
};
util::Result<std::vector<SceneMaterial>> resolveSceneMaterials(const scene::Scene& scene);

class SamplerTablesCache {
public:
    explicit SamplerTablesCache(const SamplerEnvironmentOptions& envOptions = {})
        : m_envOptions(envOptions) {}

    // Tables for `scene` and `kind`, reusing the previous call's environment tables when the
    // environment is unchanged and each material's product tables when its BRDF, parameters and
    // the environment are unchanged. Object moves never rebuild anything. `bsdf` needs no tables:
    // returns nullptr and keeps the previous tables for a later call. Errors: a material with an
    // unknown BRDF (Unsupported, naming the material, where "/materials/i/brdf").
    // When nothing the tables hold changed (an object move, a light edit, a display edit), the
    // previous call's tables are returned: the same pointer means nothing to re-upload.
    // `changed`: the invalidations of the change set that led from the previous call's scene to
    // `scene` (ChangeSet::invalidations); nullptr: unknown, compare the inputs.
    util::Result<SceneSamplerTables> update(const scene::Scene& scene, SamplerKind kind,
                                            const std::vector<scene::Invalidation>* changed = nullptr);

    const SamplerTablesRebuilds& rebuilds() const { return m_rebuilds; }

private:
    SamplerEnvironmentOptions m_envOptions;
    std::shared_ptr<const DirectionSamplerTables> m_previous;
    SamplerTablesRebuilds m_rebuilds;
};

} // namespace wavelit::render
