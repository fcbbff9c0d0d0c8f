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

// Which plugins' twins a kernel carries: bit i = registry index i (plugins::brdfIndex). A kernel
// compiled for one scene carries only the plugins its materials use ("model only what a scene
// needs"): every twin is inlined at each of the kernel's ~10 BRDF call sites, and on lavapipe all
// seven of them tripled the `wavelet` kernel's compile (92 → 30 CPU-s cold) and cost its passes
// ~15% (docs/performance.md). A material of another plugin makes uploadScene answer Unsupported,
// and the session recreates the tracer, as for the tables below.
using BrdfPluginSet = uint64_t;
inline constexpr BrdfPluginSet kAllBrdfPlugins = ~BrdfPluginSet(0);

// A kernel that binds the BRDF tables buffer (the scene's measured tables: gpu_brdf_tables.h)
// defines this as its binding number; without it the dispatch has no case for plugins that read
// a data file (`measured`), so kernels that never see such a material need not bind it.
inline constexpr const char* kBrdfTableBindingDefine = "WAVELIT_BRDF_TABLE_BINDING";

// The generated GLSL: the twins' #includes and the three dispatch functions, defining
// WAVELIT_BRDF_DISPATCH (shaders/common/brdf.glsl checks it).
std::string brdfDispatchGlsl(BrdfPluginSet plugins = kAllBrdfPlugins);

// `source` with the dispatch spliced in after its leading #version / #extension lines, followed
// by a #line directive so that compile errors keep the file's own line numbers. A source without
// any #include is returned as it is (it cannot reach common/brdf.glsl).
std::string spliceBrdfDispatch(const std::string& source, BrdfPluginSet plugins = kAllBrdfPlugins);

// vk::compileComputeShader / compileComputeShaderFile of the spliced source.
util::Result<std::vector<uint32_t>> compileWithBrdfDispatch(const std::string& source,
                                                            const std::string& name,
                                                            const vk::ShaderCompileOptions& options,
                                                            BrdfPluginSet plugins = kAllBrdfPlugins);
util::Result<std::vector<uint32_t>>
compileFileWithBrdfDispatch(const std::string& path, const vk::ShaderCompileOptions& options,
                            BrdfPluginSet plugins = kAllBrdfPlugins);

} // namespace wavelit::render
