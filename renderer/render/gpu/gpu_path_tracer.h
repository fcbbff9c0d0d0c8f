// The Vulkan compute path tracer behind createGpuPathTracer (integrator_factory.h). Each pass of
// shaders/path_tracer.comp adds 1 spp to a float-sum storage buffer; image() reads it back and
// divides by the pass count. Scene data is uploaded at creation and re-uploaded by setScene;
// applyChanges re-sends only the buffers a change set invalidates (architecture.md §5.B "What an
// edit rebuilds"). Sources: gpu_path_tracer.cpp (creation), gpu_path_tracer_upload.cpp (scene
// buffers), gpu_path_tracer_pass.cpp (passes, read-back), the class in gpu_path_tracer_impl.h.
// Driven by one thread; renderPass submits and waits on a fence, so the editor calls it from its
// render thread, never the UI thread.
//
// A pass is submitted in pieces (16x16-pixel tiles in a scattered order, one vkCmdDispatchBase
// each) sized from the measured cost per tile to take about kGpuPassPieceSeconds each, so an
// interrupt check (Integrator::setInterruptCheck) is polled every ~40 ms even when a whole pass
// takes over a minute (1600x1000 with `wavelet` on lavapipe: 71 s). The image is the same, bit
// for bit, as one dispatch per pass, and no slower (1600x1000 `bsdf`: 3.8 s a pass pieced, 4.0 s
// as one dispatch, on a loaded 2-core machine).
//
// The scene parameters are a storage buffer, not a uniform buffer: lavapipe (Mesa 22.3) re-compiles
// a shader whose control flow reads uniform-buffer values every time the pipeline is bound, with
// those values inlined, and keeps every compiled variant until the device goes: +1.3 MB per pass
// with `bsdf`, +5.8 MB with `wavelet` (docs/memory.md).
#pragma once

#include <string>

namespace wavelit::render {

// Target duration of one submitted piece of a pass (the interrupt check's polling interval).
inline constexpr double kGpuPassPieceSeconds = 0.04;

// Where shaders and BRDF snippets are read from at run time: the environment variables
// WAVELIT_SHADER_DIR / WAVELIT_PLUGIN_DIR when set, else the source-tree paths baked in by CMake.
std::string gpuShaderDirectory();
std::string gpuPluginDirectory();

} // namespace wavelit::render
