// The GLSL BRDF dispatch (brdfSample, brdfEval, brdfPdf on a material's type code), generated
// from the plugin registry when a kernel is compiled, so no shader names a plugin (issue 11).
// A plugin's type code is its registry index (plugins::brdfIndex); each plugin's GLSL twin
// (plugins::BrdfGpuTwin) is included and called by the code generated for its index. A plugin
// without a twin gets no case: the scene packer refuses its materials (gpu_scene_data.h), and
// the dispatch returns an invalid sample for an unknown code rather than another plugin's.
#pragma once

#include "util/result.h"
#include "vk/shader_compiler.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wavelit::render {

// A kernel that binds the BRDF tables buffer (the scene's measured tables: gpu_brdf_tables.h)
// defines this as its binding number; without it the dispatch has no case for plugins that read
// a data file (`measured`), so kernels that never see such a material need not bind it.
inline constexpr const char* kBrdfTableBindingDefine = "WAVELIT_BRDF_TABLE_BINDING";

// The generated GLSL: the twins' #includes and the three dispatch functions, defining
// WAVELIT_BRDF_DISPATCH (shaders/common/brdf.glsl checks it).
std::string brdfDispatchGlsl();

// `source` with the dispatch spliced in after its leading #version / #extension lines, followed
// by a #line directive so that compile errors keep the file's own line numbers. A source without
// any #include is returned as it is (it cannot reach common/brdf.glsl).
std::string spliceBrdfDispatch(const std::string& source);

// vk::compileComputeShader / compileComputeShaderFile of the spliced source.
util::Result<std::vector<uint32_t>> compileWithBrdfDispatch(const std::string& source,
                                                            const std::string& name,
                                                            const vk::ShaderCompileOptions& options);
util::Result<std::vector<uint32_t>>
compileFileWithBrdfDispatch(const std::string& path, const vk::ShaderCompileOptions& options);

} // namespace wavelit::render
