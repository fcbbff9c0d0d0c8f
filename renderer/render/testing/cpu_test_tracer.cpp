#include "render/testing/cpu_test_tracer.h"

#include "scene/bvh.h"

#include <cstdio>

namespace wavelit::render {

std::unique_ptr<CpuPathTracer> makeCpuTestTracer(std::shared_ptr<const scene::Scene> scene,
                                                 const RenderOptions& options) {
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    auto tracer = CpuPathTracer::create(std::move(scene), std::move(bvh), options, 1);
    if (!tracer.ok()) {
        std::fprintf(stderr, "CpuPathTracer::create: %s\n", tracer.error().message().c_str());
        return nullptr;
    }
    return std::move(tracer.value());
}

} // namespace wavelit::render
