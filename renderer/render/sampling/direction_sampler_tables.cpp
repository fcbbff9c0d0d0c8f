#include "render/sampling/direction_sampler_tables.h"

#include <cmath>
#include <cstdio>

namespace wavelit::render {
namespace {

// Field-for-field equality of what SamplerEnvironment::build reads (and the path, which names
// the content). Images: the same pointer, else the same size and texels (a scene copy usually
// shares the pointer; a reloaded map does not, and comparing ~1e6 texels costs ~1 ms, far less
// than a rebuild).
bool sameUpToRotation(const scene::Environment& a, const scene::Environment& b) {
    if (a.path != b.path || tablesEnvironment(a).intensity != tablesEnvironment(b).intensity ||
        a.tint != b.tint)
        return false;
    if (a.image == b.image)
        return true;
    if (!a.image || !b.image)
        return false;
    return a.image->width == b.image->width && a.image->height == b.image->height &&
           a.image->pixels == b.image->pixels;
}

bool sameEnvironment(const scene::Environment& a, const scene::Environment& b) {
    return a.rotationDeg == b.rotationDeg && sameUpToRotation(a, b);
}

bool sameEnvOptions(const SamplerEnvironmentOptions& a, const SamplerEnvironmentOptions& b) {
    return a.maxLevel == b.maxLevel && a.minLevel == b.minLevel;
}

} // namespace

scene::Environment tablesEnvironment(const scene::Environment& env) {
    scene::Environment out = env;
    if (env.intensity > 0.0f && std::isfinite(env.intensity))
        out.intensity = 1.0f;
    return out;
}

bool sameSampling(const SamplerMaterial& a, const SamplerMaterial& b) {
    return a.brdf == b.brdf && a.params == b.params;
}

std::shared_ptr<const DirectionSamplerTables>
DirectionSamplerTables::build(const scene::Environment& env, std::vector<SamplerMaterial> materials,
                              SamplerKind kind, const SamplerEnvironmentOptions& envOptions) {
    return build(env, std::move(materials), kind, nullptr, envOptions);
}

std::shared_ptr<const DirectionSamplerTables>
DirectionSamplerTables::build(const scene::Environment& env, std::vector<SamplerMaterial> materials,
                              SamplerKind kind, const DirectionSamplerTables* previous,
                              const SamplerEnvironmentOptions& envOptions) {
    auto t = std::make_shared<DirectionSamplerTables>();
    t->m_kind = kind;
    t->m_source = env;
    t->m_envOptions = envOptions;
    const bool sameOptions = previous && sameEnvOptions(previous->m_envOptions, envOptions);
    t->m_envReused = sameOptions && sameEnvironment(previous->m_source, env);
    t->m_envRotated = sameOptions && !t->m_envReused && sameUpToRotation(previous->m_source, env);
    if (t->m_envReused)
        t->m_env = previous->m_env;
    else if (t->m_envRotated)
        t->m_env = std::make_shared<const SamplerEnvironment>(
            previous->m_env->rotatedTo(tablesEnvironment(env)));
    else
        t->m_env = std::make_shared<const SamplerEnvironment>(
            SamplerEnvironment::build(tablesEnvironment(env), envOptions));
    t->m_materials = std::move(materials);
    if (kind != SamplerKind::Wavelet)
        return t;
    for (const SamplerMaterial& m : t->m_materials) {
        // Product tables are a function of (env, plugin, params), in the env-local frame:
        // reusable over the same env, turned or not.
        std::shared_ptr<const MaterialProductTables> product;
        if (t->m_envReused || t->m_envRotated)
            for (size_t i = 0; i < previous->m_products.size() && !product; ++i)
                if (sameSampling(previous->m_materials[i], m))
                    product = previous->m_products[i];
        t->m_productReused.push_back(product != nullptr);
        if (!product)
            product = std::make_shared<const MaterialProductTables>(MaterialProductTables::build(
                *t->m_env, chooseProductPolicy(*m.brdf, m.params, *t->m_env)));
        t->m_products.push_back(std::move(product));
    }
    return t;
}

const MaterialProductTables* DirectionSamplerTables::productTables(size_t i) const {
    return i < m_products.size() ? m_products[i].get() : nullptr;
}

bool DirectionSamplerTables::anyProduct() const {
    for (const auto& p : m_products)
        if (p && p->policy().mode == ProductMode::Product)
            return true;
    return false;
}

bool DirectionSamplerTables::productTablesReused(size_t i) const {
    return i < m_productReused.size() && m_productReused[i];
}

std::string DirectionSamplerTables::report() const {
    char line[200];
    std::snprintf(line, sizeof line,
                  "sampler %s: env octahedral %d^2 (%s), %.1f KiB, built in %.1f ms%s\n",
                  samplerKindName(m_kind), 1 << m_env->level(),
                  m_env->hasLight() ? "lit" : "black", double(m_env->bytes()) / 1024.0,
                  m_env->buildSeconds() * 1e3,
                  m_envReused ? " (reused)" : m_envRotated ? " (the previous, turned)" : "");
    std::string out = line;
    for (size_t i = 0; i < m_products.size(); ++i)
        out += "  material " + m_materials[i].name + ": " + m_products[i]->describe() +
               (m_productReused[i] ? " (reused)" : "") + "\n";
    return out;
}

} // namespace wavelit::render
