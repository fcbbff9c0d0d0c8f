// BRDF plugins (architecture.md §2 "plugins/"): one per .cpp file, looked up by the name a Material
// stores (scene.h: Material::brdf). Each has a GLSL twin (<name>.glsl) that the Vulkan tracer
// splices in; both compute docs/estimator.md's formulas, and tests compare them.
//
// Contract shared by every plugin:
// - Directions are unit vectors in the LOCAL shading frame, z = shading normal; wo points away
//   from the surface toward the viewer, wi toward the light.
// - eval returns f (sr^-1), WITHOUT the cosine factor; 0 when wo or wi is at or below the horizon.
// - sample draws wi from u1, u2 in [0,1) and returns f(wo, wi) and the pdf in SOLID ANGLE; a
//   direction at or below the horizon is an invalid sample (the path ends; docs/estimator.md).
// - pdf(wo, wi) equals what sample returns for that wi (tests check it), 0 below the horizon.
// - invert(wo, wi) returns the (u1, u2) that sample maps to wi (architecture.md §9: samplers round-trip),
//   or nothing where no u reaches wi (below the horizon, wo behind the surface).
// - Plugins are stateless and immutable, so one instance is shared by every thread.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace wavelit::plugins {

struct BrdfTable; // plugins/brdf_table.h

// The material parameters a BRDF reads (scene::Material carries the same fields; each plugin
// reads only those its parameters() declare).
// A constructor rather than an aggregate: most callers give the colour and roughness only.
struct BrdfParams {
    BrdfParams() = default;
    BrdfParams(const glm::vec3& color, float r, float aniso = 0.0f,
               std::shared_ptr<const BrdfTable> data = nullptr)
        : baseColor(color), roughness(r), anisotropy(aniso), table(std::move(data)) {}

    glm::vec3 baseColor{0.8f};
    float roughness = 0.5f;  // [0, 1]; GGX alpha = roughness^2 (architecture.md §3)
    float anisotropy = 0.0f; // [0, 1]; `ward`: 0 isotropic, toward 1 stretched along the tangent
    // `measured`: the table loaded from the material's brdfFile (null for every other plugin).
    std::shared_ptr<const BrdfTable> table;
    bool operator==(const BrdfParams&) const = default;
};

struct BrdfSample {
    glm::vec3 wi{0.0f, 0.0f, 1.0f};
    glm::vec3 f{0.0f};
    float pdf = 0.0f; // solid angle
    bool valid = false;
};

// Parameter metadata, so the property registry and the editor's panels can describe plugin
// parameters without knowing the plugin (architecture.md §9: "plugins register their parameters the same
// way"). `name` is the Material field / JSON key.
enum class BrdfParameterType { Color, Float, File }; // File: a path relative to the scene file

struct BrdfParameterInfo {
    const char* name;
    const char* label;
    BrdfParameterType type;
    float minValue;
    float maxValue;
    glm::vec3 defaultValue; // Float parameters use .x
    const char* tooltip;
};

// Lobe traits: what the samplers and the GPU tracer need to know about a plugin without naming it
// (issue 11). The axis decides where the env-product and oracle windows are centred.
enum class BrdfLobeAxis {
    Normal, // diffuse: the lobe sits about the shading normal
    Mirror, // glossy: the lobe sits about the mirror direction of wo
};

// How a lobe falls off past its half-width: the product sampler's window must hold the tail
// (render/sampling/product/env_product_tables.cpp). PowerLaw: GGX's theta^-4 keeps ~10% of the
// lobe beyond 3 half-widths. Gaussian: exp(-tan^2/alpha^2) (Beckmann, Ward) and cos^n (Phong,
// Blinn-Phong) hold < 1% there.
enum class BrdfTail {
    PowerLaw,
    Gaussian,
};

struct BrdfLobeWidth {
    // Angular half-width of the lobe about its axis (radians): the scale the env product resolves.
    double halfWidth = 0.0;
    // Half-angle of the cone about the axis that holds the lobe (radians; >= pi: the whole sphere).
    // The oracle fits its window to it (render/sampling/oracle_sampler.h).
    double capHalfAngle = 0.0;
    BrdfTail tail = BrdfTail::PowerLaw;
};

// The GLSL twin: a snippet file in plugins/ and the functions it defines, with the signatures
//   bool S(vec3 baseColor, float roughness, vec3 wo, float u1, float u2, out vec3 wi, out vec3 f, out float pdf)
//   vec3 E(vec3 baseColor, float roughness, vec3 wo, vec3 wi)
//   float P(float roughness, vec3 wo, vec3 wi)
// The GPU tracer splices the snippets in and generates the dispatch on the registry index.
// Empty strings: the plugin has no GPU twin (the GPU tracer refuses it by name).
//
// A plugin that reads one more scalar parameter in [0, 1] (`ward`'s anisotropy) names it in
// typeParameter: the GPU carries it in the material's type code (gpuBrdfType: registry index +
// kBrdfTypeCodePlugins × the value in steps of 1/kBrdfTypeParameterSteps), and the three functions
// then take it as a first `float` argument. The plugin rounds the value with
// brdfTypeParameterStep itself, so both tracers compute with the same number.
inline constexpr unsigned kBrdfTypeCodePlugins = 256;    // plugin index = code % 256
inline constexpr unsigned kBrdfTypeParameterSteps = 4096; // code < 2^24: exact in a float
inline float brdfTypeParameterStep(float v) {
    const float c = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
    return float(unsigned(c * float(kBrdfTypeParameterSteps) + 0.5f)) / float(kBrdfTypeParameterSteps);
}

struct BrdfGpuTwin {
    const char* snippet = "";
    const char* sampleFn = "";
    const char* evalFn = "";
    const char* pdfFn = "";
    float (*typeParameter)(const BrdfParams&) = nullptr;
};

// Many directions for evalBatch, as three arrays (structure of arrays: what a vectorised loop
// reads), `count` entries each, in the local shading frame like eval's wi.
struct BrdfDirections {
    const float* x = nullptr;
    const float* y = nullptr;
    const float* z = nullptr;
    size_t count = 0;
};

// evalBatch's output: f per direction, one array per channel (`count` entries each).
struct BrdfValues {
    float* r = nullptr;
    float* g = nullptr;
    float* b = nullptr;
};

class Brdf {
public:
    virtual ~Brdf() = default;
    virtual const char* name() const = 0;
    virtual std::span<const BrdfParameterInfo> parameters() const = 0;
    virtual BrdfLobeAxis lobeAxis() const = 0;
    virtual BrdfLobeWidth lobeWidth(const BrdfParams& p) const = 0;
    virtual BrdfGpuTwin gpuTwin() const = 0;

    virtual glm::vec3 eval(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const = 0;
    // eval at every wi of `wi` for one wo: out[i] = eval(p, wo, wi[i]) to float rounding (the
    // overrides compute the same operations in the same order, so in practice bit for bit). The
    // relighting preview evaluates ~500 directions per point this way (docs/relighting.md §7.0f):
    // one call instead of one virtual call each, and a loop the compiler vectorises. This default
    // loops over eval, so a plugin without an override still works.
    virtual void evalBatch(const BrdfParams& p, const glm::vec3& wo, const BrdfDirections& wi,
                           const BrdfValues& out) const {
        for (size_t i = 0; i < wi.count; ++i) {
            const glm::vec3 f = eval(p, wo, glm::vec3(wi.x[i], wi.y[i], wi.z[i]));
            out.r[i] = f.x;
            out.g[i] = f.y;
            out.b[i] = f.z;
        }
    }
    virtual BrdfSample sample(const BrdfParams& p, const glm::vec3& wo, float u1, float u2) const = 0;
    virtual float pdf(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const = 0;
    virtual std::optional<glm::vec2> invert(const BrdfParams& p, const glm::vec3& wo,
                                            const glm::vec3& wi) const = 0;
};

// nullptr when no plugin has that name.
const Brdf* findBrdf(std::string_view name);
// Names of every registered plugin, in registration order.
std::vector<std::string> brdfNames();
// Every registered plugin, in registration order; a plugin's index is its GPU type code.
std::span<const Brdf* const> brdfRegistry();
// The registry index of `brdf` (its GPU type code); -1 when it is not registered.
int brdfIndex(const Brdf& brdf);
// A material parameter's tooltip: each plugin that reads it, "name: its tooltip", joined by "; "
// (a shared parameter means different things: albedo for one, F0 for another).
std::string brdfParameterTooltip(std::string_view parameter);
// The BRDF a new material gets: the first registered plugin.
const char* defaultBrdfName();
// What is wrong with a plugin's traits (an unknown lobe axis, a non-finite or non-positive lobe
// width), empty when they are coherent. Checked where a plugin is used, so a bad plugin is an
// error with its name, never another plugin's policy.
std::string brdfTraitsProblem(const Brdf& brdf);
// Whether the plugin reads a data file (a parameter of type File: `brdfFile`), which the scene
// loader reads into BrdfParams::table (plugins/brdf_table.h).
bool brdfReadsFile(const Brdf& brdf);
// Same for the GLSL twin: empty when the plugin has a snippet and all three functions.
std::string brdfGpuTwinProblem(const Brdf& brdf);

} // namespace wavelit::plugins
