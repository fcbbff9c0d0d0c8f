// The Vulkan compute path tracer behind createGpuPathTracer (integrator_factory.h). One dispatch
// of shaders/path_tracer.comp per pass adds 1 spp to a float-sum storage buffer; image() reads it
// back and divides by the pass count. Scene data is uploaded once at creation (a new scene makes
// a new integrator until change sets arrive, issue 5/6). Driven by one thread; renderPass submits
// and waits on a fence, so the editor calls it from its render thread, never the UI thread.
#pragma once

#include <string>

namespace wavelit::render {

// Where shaders and BRDF snippets are read from at run time: the environment variables
// WAVELIT_SHADER_DIR / WAVELIT_PLUGIN_DIR when set, else the source-tree paths baked in by CMake.
std::string gpuShaderDirectory();
std::string gpuPluginDirectory();

} // namespace wavelit::render
