// What the Vulkan path tracer's tests share (gpu_path_tracer_test.cpp,
// gpu_path_tracer_scene_swap_test.cpp; the light tests take the options too): their options
// (validation on, 64^2 by default: lavapipe shares two CPU cores with everything else), a small
// gradient environment, the tracer and its passes. Test-only (GoogleTest): included by test
// files of the render test executable.
#pragma once

#include "render/session/integrator.h"
#include "render/session/integrator_factory.h"
#include "render/session/render_options.h"
#include "scene/bvh.h"
#include "scene/scene.h"
#include "util/image.h"

#include <gtest/gtest.h>

#include <memory>

namespace wavelit::render::gpu_tracer_test {

inline constexpr int kSize = 64;

inline RenderOptions testOptions(int bounces, int width = kSize, int height = kSize) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.bounces = bounces;
    o.seed = 7;
    o.device = DeviceChoice::Vulkan;
    o.validation = true;
    return o;
}

// A 32 x 16 equirect image: a horizontal colour ramp, bright sky over a dim ground.
inline std::shared_ptr<util::ImageRGB> gradientEnvironment() {
    auto env = std::make_shared<util::ImageRGB>(32, 16);
    for (int y = 0; y < env->height; ++y)
        for (int x = 0; x < env->width; ++x)
            env->at(x, y) = glm::vec3(0.2f + x / 32.0f, y < 8 ? 2.0f : 0.1f, 0.5f);
    return env;
}

inline std::unique_ptr<Integrator> makeGpu(const std::shared_ptr<scene::Scene>& scene,
                                           const RenderOptions& options) {
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    auto gpu = createGpuPathTracer(scene, bvh, options);
    if (!gpu)
        ADD_FAILURE() << gpu.error().message();
    return gpu ? std::move(gpu.value()) : nullptr;
}

inline util::ImageRGB renderPasses(Integrator& integrator, int passes) {
    for (int i = 0; i < passes; ++i) {
        auto status = integrator.renderPass();
        EXPECT_TRUE(status.ok()) << status.error().message();
    }
    auto img = integrator.image();
    EXPECT_TRUE(img.ok());
    return img ? *img : util::ImageRGB();
}

} // namespace wavelit::render::gpu_tracer_test
