// The scene's measured BRDF tables (plugins/brdf_table.h) as the Vulkan tracer reads them: one
// storage buffer of floats that plugins/measured.glsl indexes. First a 1 x 1 x 1 table of zeros
// (offset 0: a material whose file is not loaded), then each distinct table once, at an
// offset that is a multiple of 4: (Nθh, Nθd, Nφd, 0), then the red, green and blue blocks of
// BrdfTable::f. A material finds its table by that offset, which the material packer
// (gpu_scene_data.cpp) writes into its roughness slot.
#pragma once

#include "plugins/brdf_table.h"
#include "scene/scene.h"
#include "util/result.h"

#include <cstdint>
#include <map>
#include <vector>

namespace wavelit::render {

// Offsets travel in a float (the material's roughness slot), exact below 2^24: three full MERL
// tables (4.4M floats each) fit.
inline constexpr uint32_t kMaxGpuBrdfTableOffset = 1u << 24;

struct GpuBrdfTables {
    std::vector<float> floats;
    std::map<const plugins::BrdfTable*, uint32_t> offsetOf; // nullptr: 0, the zero table
};

// Errors: a table that would start at or past kMaxGpuBrdfTableOffset (Unsupported, naming the
// material and its file).
util::Result<GpuBrdfTables> packGpuBrdfTables(const scene::Scene& scene);

} // namespace wavelit::render
