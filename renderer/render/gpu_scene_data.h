// The scene as the Vulkan path tracer reads it (shaders/path_tracer.comp): a std140 parameter
// block, std430 materials and the environment texels, packed on the CPU so the packing can be
// tested without a device. The BVH arrays (scene/bvh.h) are uploaded as they are.
#pragma once

#include "render/render_options.h"
#include "scene/bvh.h"
#include "scene/scene.h"
#include "util/result.h"

#include <cstdint>
#include <vector>

namespace wavelit::render {

// BRDF type codes shared with shaders/common/brdf.glsl.
inline constexpr uint32_t kGpuBrdfLambert = 0;
inline constexpr uint32_t kGpuBrdfGgx = 1;

// Mirrors `uniform Params` in path_tracer.comp (std140: all members vec4/uvec4).
struct GpuParams {
    float camPosition[4];
    float camForward[4]; // w = tan(vfov / 2)
    float camRight[4];   // w = aspect
    float camUp[4];
    float envScale[4];    // rgb = intensity * tint
    float envRotation[4]; // cos yaw, sin yaw
    uint32_t size[4];     // width, height, bounces, triangle count
    uint32_t envSize[4];  // env width, env height (0 = constant env), material count
};
static_assert(sizeof(GpuParams) == 128);

// Mirrors `struct Material` in path_tracer.comp (std430).
struct GpuMaterial {
    float baseColorRoughness[4];
    float emissionType[4]; // rgb emission, a = BRDF type code
};
static_assert(sizeof(GpuMaterial) == 32);

struct GpuSceneData {
    GpuParams params{};
    // The scene's materials in order, then the default Material{} that bvh.cpp's
    // "unknown material" index (materials.size()) points at.
    std::vector<GpuMaterial> materials;
    std::vector<float> envTexels; // RGB per texel, row-major, row 0 = top (v = 0)
};

// Errors: a material whose BRDF has no GLSL twin (Unsupported, naming the material).
util::Result<GpuSceneData> packGpuScene(const scene::Scene& scene, const scene::Bvh& bvh,
                                        const RenderOptions& options);

// Seed of pass `pass` (docs/estimator.md "Random numbers"): seed ^ (pass * 0x9E3779B97F4A7C15).
uint64_t gpuPassSeed(uint64_t seed, int pass);

} // namespace wavelit::render
