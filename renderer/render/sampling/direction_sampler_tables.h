// The tables every direction sampler of a scene draws from (issue 6; direction_sampler.h): the
// environment's sampling view and, for `wavelet`, each material's product tables, built once per
// scene and again, piece by piece, after change sets that invalidate a piece.
#pragma once

#include "plugins/brdf.h"
#include "render/sampling/product/env_product_tables.h"
#include "render/sampling/sampler_environment.h"
#include "render/session/render_options.h"
#include "scene/scene.h"

#include <memory>
#include <string>
#include <vector>

namespace wavelit::render {

// A material as the samplers need it (scene::Material resolved to its plugin).
struct SamplerMaterial {
    std::string name;
    const plugins::Brdf* brdf = nullptr;
    plugins::BrdfParams params;
};

// The same plugin with the same parameters: the same tables over the same env (the name is only a
// label).
bool sameSampling(const SamplerMaterial& a, const SamplerMaterial& b);

// The environment the tables are built from: `env` at intensity 1 where its intensity is positive
// (and finite). Everything a sampler reads from the tables is a pdf (normalised: the same at any
// intensity) or a ratio of env moments (the mixture shares: both sides scale alike), so an
// intensity edit changes no table, and building them always at 1 makes the kept tables equal, bit
// for bit, to a fresh build at the new intensity. Intensity 0 (black) and invalid values are
// kept: no light means no env technique.
scene::Environment tablesEnvironment(const scene::Environment& env);

class DirectionSamplerTables {
public:
    // Builds the env tables and, for kind Wavelet, the product tables of every material
    // (materials not in the list get none: list only those the scene uses, architecture.md §7).
    static std::shared_ptr<const DirectionSamplerTables>
    build(const scene::Environment& env, std::vector<SamplerMaterial> materials, SamplerKind kind,
          const SamplerEnvironmentOptions& envOptions = {});

    // The same tables, sharing (not copying) `previous`'s pieces whose inputs are unchanged, so a
    // change set rebuilds only what it invalidates (architecture.md §5): the SamplerEnvironment when
    // `env` equals previous->sourceEnvironment() field for field (path, image content, rotation,
    // tint, and intensity as tablesEnvironment sees it: an intensity edit keeps the tables) with
    // the same envOptions, and a copy turned to the new yaw when only the
    // rotation differs (every table is env-local); a material's MaterialProductTables when, in
    // addition, some previous material has the same plugin and BrdfParams (the tables depend on
    // the env and on the material only through chooseProductPolicy; comparing the inputs rather
    // than the policy keeps this correct whatever the policy reads). previous may be nullptr.
    // The result is identical in content to build() without `previous`.
    static std::shared_ptr<const DirectionSamplerTables>
    build(const scene::Environment& env, std::vector<SamplerMaterial> materials, SamplerKind kind,
          const DirectionSamplerTables* previous, const SamplerEnvironmentOptions& envOptions = {});

    SamplerKind kind() const { return m_kind; }
    const SamplerEnvironment& environment() const { return *m_env; }
    // The env the tables were built for (their pieces may have been kept since across intensity
    // edits: tablesEnvironment of it equals that of the current one).
    const scene::Environment& sourceEnvironment() const { return m_source; }
    const SamplerMaterial& material(size_t i) const { return m_materials[i]; }
    size_t materialCount() const { return m_materials.size(); }
    // nullptr unless kind == Wavelet.
    const MaterialProductTables* productTables(size_t i) const;
    // Whether some material's vertices draw from a per-hit product (policy mode Product): a
    // Vulkan kernel of tables without one is compiled without the product code (issue 12).
    bool anyProduct() const;
    // Whether build() took the piece from `previous` instead of building it (false without one).
    bool environmentReused() const { return m_envReused; }
    // Whether the env tables are `previous`'s turned to a new rotation (SamplerEnvironment::
    // rotatedTo): a new object, with every product table reused (they are env-local too).
    bool environmentRotated() const { return m_envRotated; }
    bool productTablesReused(size_t i) const;
    // Multi-line report: env resolution, per-material choice and reason, bytes, build times
    // (of the build that made each piece; "reused" marks pieces taken from `previous`).
    std::string report() const;

private:
    SamplerKind m_kind = SamplerKind::Wavelet;
    scene::Environment m_source;
    SamplerEnvironmentOptions m_envOptions;
    // Shared with the tables this one was built from, and with those built from it: immutable.
    std::shared_ptr<const SamplerEnvironment> m_env;
    bool m_envReused = false;
    bool m_envRotated = false;
    std::vector<SamplerMaterial> m_materials;
    std::vector<std::shared_ptr<const MaterialProductTables>> m_products;
    std::vector<bool> m_productReused;
};

} // namespace wavelit::render
