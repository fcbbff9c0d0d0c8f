#include "render/testing/test_integrator.h"

#include "render/session/integrator_factory.h"
#include "scene/bvh.h"

namespace wavelit::render {

util::Result<std::unique_ptr<Integrator>> makeTestIntegrator(std::shared_ptr<const scene::Scene> scene,
                                                             const RenderOptions& options) {
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    switch (options.device) {
    case DeviceChoice::Vulkan:
        return createGpuPathTracer(std::move(scene), std::move(bvh), options);
    case DeviceChoice::Cpu:
        return createCpuPathTracer(std::move(scene), std::move(bvh), options);
    case DeviceChoice::Auto:
        break;
    }
    return util::makeError(util::ErrorKind::Usage, "", "a test names its device (Vulkan or Cpu)");
}

} // namespace wavelit::render
