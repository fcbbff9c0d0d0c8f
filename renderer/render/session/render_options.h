// Options of a render: what the CLI flags (architecture.md §6) and the editor set.
#pragma once

#include "util/result.h"

#include <cstdint>
#include <optional>
#include <string>

namespace wavelit::render {

enum class DeviceChoice { Auto, Vulkan, Cpu };

// Direction samplers for the speed/error report (architecture.md §5.B). The CPU reference tracer runs all
// of them (render/sampling/direction_sampler.h), and so does the Vulkan tracer (shaders/common/
// direction_sampler.glsl; its Oracle is dense at a coarser grid, gpu_sampler_data.h).
// The CLI and the editor default to Wavelet; RenderOptions' own default is Bsdf (no tables).
enum class SamplerKind { Uniform, Cosine, Bsdf, Env, Mis, Wavelet, Oracle };

util::Result<DeviceChoice> parseDeviceChoice(const std::string& text);
util::Result<SamplerKind> parseSamplerKind(const std::string& text);
const char* samplerKindName(SamplerKind kind);
const char* deviceChoiceName(DeviceChoice kind);

struct RenderOptions {
    int width = 512;
    int height = 512;
    int bounces = 4;     // scattering events per path (1 = direct lighting only)
    uint64_t seed = 1;
    // The index of the first pass after a reset: pass k of this render draws the random numbers
    // of pass firstPass + k (docs/estimator.md "Random numbers"), so renders of disjoint pass
    // ranges are parts of one longer render (`wavelit-cli render --passes`, docs/farm.md).
    int firstPass = 0;
    DeviceChoice device = DeviceChoice::Auto;
    SamplerKind sampler = SamplerKind::Bsdf;
    // Vulkan physical device: index or case-insensitive name substring; empty = prefer a hardware
    // GPU, else lavapipe. The environment variable WAVELIT_VK_DEVICE overrides an empty value.
    std::string vulkanDevice;
    // Vulkan validation layers: on when true, or when WAVELIT_VK_VALIDATION=1; tests turn it on.
    bool validation = false;
    // LightMix (docs/lightmix.md): also accumulate one radiance layer per light group
    // (light_groups.h). Off: no layers are allocated and the tracers add nothing.
    bool lightGroups = false;
};

} // namespace wavelit::render
