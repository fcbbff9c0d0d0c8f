// Factories of the two integrators. RenderSession picks one by RenderOptions::device; the scene and
// BVH are shared (immutable) with the integrator for its lifetime.
#pragma once

#include "render/session/integrator.h"
#include "render/session/render_options.h"
#include "scene/bvh.h"
#include "scene/scene.h"
#include "util/result.h"

#include <memory>

namespace wavelit::render {

// Vulkan compute path tracer (gpu_path_tracer.cpp). Errors: no Vulkan device, shader compile
// failure (message names the shader file and line), out of device memory.
util::Result<std::unique_ptr<Integrator>>
createGpuPathTracer(std::shared_ptr<const scene::Scene> scene, std::shared_ptr<const scene::Bvh> bvh,
                    const RenderOptions& options);

// CPU reference path tracer (cpu_path_tracer.cpp): the same estimator (docs/estimator.md), on
// std::thread workers.
util::Result<std::unique_ptr<Integrator>>
createCpuPathTracer(std::shared_ptr<const scene::Scene> scene, std::shared_ptr<const scene::Bvh> bvh,
                    const RenderOptions& options);

} // namespace wavelit::render
