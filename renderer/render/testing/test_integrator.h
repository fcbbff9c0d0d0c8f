// The integrator of options.device (Vulkan or Cpu; Auto is refused) over `scene` with its own
// BVH: for tests that run one estimator on both tracers and compare them.
#pragma once

#include "render/session/integrator.h"
#include "render/session/render_options.h"
#include "scene/scene.h"
#include "util/result.h"

#include <memory>

namespace wavelit::render {

util::Result<std::unique_ptr<Integrator>> makeTestIntegrator(std::shared_ptr<const scene::Scene> scene,
                                                             const RenderOptions& options);

} // namespace wavelit::render
