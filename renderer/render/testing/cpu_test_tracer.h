// A CPU reference tracer over `scene` with its own BVH, one worker thread: what the CPU tracer's
// tests render with. On failure the error goes to stderr and the result is null, so a test's
// ASSERT_TRUE(tracer) stops it with the reason printed.
#pragma once

#include "render/reference/cpu_path_tracer.h"

#include <memory>

namespace wavelit::render {

std::unique_ptr<CpuPathTracer> makeCpuTestTracer(std::shared_ptr<const scene::Scene> scene,
                                                 const RenderOptions& options);

} // namespace wavelit::render
