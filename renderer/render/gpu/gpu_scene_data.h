// The scene as the Vulkan path tracer reads it (shaders/path_tracer.comp): a std140 parameter
// block, std430 materials, the environment texels and the analytic lights, packed on the CPU so
// the packing can be tested without a device. The BVH arrays (scene/bvh.h) are uploaded as they
// are.
#pragma once

#include "plugins/brdf.h"
#include "render/gpu/brdf_shader_source.h"
#include "render/gpu/gpu_brdf_tables.h"
#include "render/session/render_options.h"
#include "scene/bvh.h"
#include "scene/scene.h"
#include "util/result.h"

#include <cstdint>
#include <vector>

namespace wavelit::render {

// Light type codes shared with shaders/common/lights.glsl.
inline constexpr uint32_t kGpuLightPoint = 0;
inline constexpr uint32_t kGpuLightSphere = 1;
inline constexpr uint32_t kGpuLightRect = 2;
inline constexpr uint32_t kGpuLightSpot = 3;
inline constexpr uint32_t kGpuLightSun = 4;

// A BRDF's type code in GpuMaterial::emissionType.w: its plugin registry index, which the
// dispatch generated from the registry switches on (render/gpu/brdf_shader_source.h).
uint32_t gpuBrdfType(const plugins::Brdf& brdf);
// The type code of a material: the index, plus the plugin's type parameter where it has one
// (plugins/brdf.h: BrdfGpuTwin::typeParameter, e.g. `ward`'s anisotropy).
uint32_t gpuBrdfType(const plugins::Brdf& brdf, const plugins::BrdfParams& params);

// Mirrors `uniform Params` in path_tracer.comp (std140: all members vec4/uvec4).
struct GpuParams {
    float camPosition[4];
    float camForward[4]; // w = tan(vfov / 2)
    float camRight[4];   // w = aspect
    float camUp[4];
    float envScale[4];    // rgb = intensity * tint
    float envRotation[4]; // cos yaw, sin yaw
    uint32_t size[4];     // width, height, bounces, triangle count
    uint32_t envSize[4];  // env width, env height (0 = constant env), material count, light count
    float lightInfo[4];   // x = light selection probability 1/n (LightSet), 0 without lights
    // Direction samplers (gpu_sampler_data.h; set by the driver, zero for `bsdf`):
    uint32_t samplerInfo[4]; // kind code, env lit (0/1), word offset of 8^2 env averages, env level
    float samplerEnv[4];     // x = mean luminance of the sampler's env map, y = `mis`'s roulette c
};
static_assert(sizeof(GpuParams) == 176);

// Mirrors `struct Material` in path_tracer.comp (std430).
struct GpuMaterial {
    float baseColorRoughness[4];
    float emissionType[4]; // rgb emission, a = BRDF type code
};
static_assert(sizeof(GpuMaterial) == 32);

// Mirrors `struct Light` in shaders/common/lights.glsl (std430): one analytic light with the
// constants LightSampler's constructor derives (render/lights/light_sampler.h gives the units), computed
// the same way in double.
struct GpuLight {
    float positionType[4]; // xyz position, w = type code (a zero-radius sphere is a point)
    float normalRadius[4]; // xyz normalised direction, w = sphere radius
    float emissionArea[4]; // rgb emission (L, I or E), w = rect area
    float axisUInner[4];   // xyz rect half-extent axis U, w = spot cos(inner)
    float axisVOuter[4];   // xyz rect half-extent axis V, w = spot cos(outer)
    float sun[4];          // x = sin^2(theta_s), y = 1 - cos(theta_s), z = 1 for delta lights
};
static_assert(sizeof(GpuLight) == 96);

GpuLight packGpuLight(const scene::Light& light);

struct GpuSceneData {
    GpuParams params{};
    // The scene's materials in order, then the default Material{} that bvh.cpp's
    // "unknown material" index (materials.size()) points at.
    std::vector<GpuMaterial> materials;
    std::vector<float> envTexels; // RGB per texel, row-major, row 0 = top (v = 0)
    std::vector<GpuLight> lights; // scene.lighting.lights in order
    std::vector<float> brdfTables; // the measured BRDF tables (gpu_brdf_tables.h), never empty
    // Some material reads a loaded table: only then does the kernel carry the table-reading
    // plugins and their binding (a material without its file reads the zero table: f = 0,
    // what the kernel without them answers too).
    bool usesBrdfTables = false;
    // The plugins the materials use (the default material's included): only their twins are
    // compiled into the scene's kernel (brdf_shader_source.h).
    BrdfPluginSet brdfPlugins = 0;
};

// Errors: a material whose BRDF has no GLSL twin (Unsupported, naming the material).
// packEnvTexels false: envTexels stays empty (an update that keeps the texels on the device);
// params.envSize is filled either way.
util::Result<GpuSceneData> packGpuScene(const scene::Scene& scene, const scene::Bvh& bvh,
                                        const RenderOptions& options, bool packEnvTexels = true);


} // namespace wavelit::render
