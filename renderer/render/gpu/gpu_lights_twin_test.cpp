// The analytic lights' GLSL twin (shaders/common/lights.glsl) against LightSampler
// (light_sampler.cpp, light_spherical_rect.cpp): the same (light, p, u1, u2, probe direction)
// through sample, pdf and evalHit on the Vulkan device and on the CPU. architecture.md §9: a C++ function
// and its GLSL twin are never left without a test comparing them.
#include "render/gpu/gpu_path_tracer.h"
#include "render/gpu/gpu_scene_data.h"
#include "render/lights/light_sampler.h"
#include "util/rng.h"
#include "vk/buffer.h"
#include "vk/command_runner.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"
#include "vk/shader_compiler.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace wavelit::render {
namespace {

// Per case: in = (p.xyz, u1), (probe.xyz, u2), (light index, ...); out = (wi.xyz, valid),
// (value.rgb, pdf), (distance, delta, pdf at probe, probe hits), (probe hit t, ...).
const char* kKernel = R"(#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/lights.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Lights { Light lights[]; };
layout(std430, binding = 1) readonly buffer In { vec4 inputs[]; };
layout(std430, binding = 2) buffer Out { vec4 outputs[]; };
layout(push_constant) uniform Push { uint count; } pc;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) return;
    vec4 a = inputs[3 * i], b = inputs[3 * i + 1], c = inputs[3 * i + 2];
    Light l = lights[uint(c.x)];
    LightSample s = lightSample(l, a.xyz, a.w, b.w);
    float t;
    bool hit = lightEvalHit(l, a.xyz, b.xyz, kFloatMax, true, t);
    outputs[4 * i] = vec4(s.wi, s.valid ? 1.0 : 0.0);
    outputs[4 * i + 1] = vec4(s.value, s.pdf);
    outputs[4 * i + 2] =
        vec4(s.distance, s.delta ? 1.0 : 0.0, lightPdf(l, a.xyz, b.xyz), hit ? 1.0 : 0.0);
    outputs[4 * i + 3] = vec4(t, 0.0, 0.0, 0.0);
}
)";

// Relative agreement of float formulas evaluated by LLVM and by the C++ compiler (sin, cos, atan
// and sqrt within a few ulps; the spherical rectangle's S cancels to ~1e-6 absolute, so 1e-3
// relative leaves margin for S >= 1e-2). Directions: absolute.
constexpr float kTolerance = 1e-3f;

bool near(float a, float b) {
    return std::abs(a - b) <= kTolerance * std::max(1.0f, std::abs(b));
}

TEST(GpuLightsTwin, GlslMatchesLightSampler) {
    auto ctx = vk::Context::create({"", true});
    ASSERT_TRUE(ctx.ok()) << ctx.error().message();
    auto spirv = vk::compileComputeShader(kKernel, "lights_twin_test.comp",
                                          {{gpuShaderDirectory(), gpuPluginDirectory()}, {}});
    ASSERT_TRUE(spirv.ok()) << spirv.error().message();

    std::vector<scene::Light> lights(7);
    lights[0].type = scene::LightType::Point;
    lights[1].type = scene::LightType::Sphere;
    lights[1].radius = 0.4f;
    lights[2].type = scene::LightType::Rect;
    lights[2].direction = glm::vec3(0.1f, -1.0f, 0.2f);
    lights[2].size = glm::vec2(1.5f, 0.5f);
    lights[3].type = scene::LightType::Spot;
    lights[3].direction = glm::vec3(0.2f, -1.0f, 0.0f);
    lights[4].type = scene::LightType::Sun;
    lights[4].direction = glm::vec3(-0.3f, -1.0f, 0.2f);
    lights[4].angularDiameterDeg = 0.53f;
    lights[5].type = scene::LightType::Sun;
    lights[5].angularDiameterDeg = 0.0f;
    lights[6].type = scene::LightType::Rect; // tiny and far: the area-sampling branch
    lights[6].size = glm::vec2(0.05f, 0.05f);
    std::vector<GpuLight> packed;
    std::vector<LightSampler> cpu;
    for (const scene::Light& l : lights) {
        packed.push_back(packGpuLight(l));
        cpu.emplace_back(l);
    }

    struct Case {
        int light;
        glm::vec3 p, probe;
        float u1, u2;
    };
    std::vector<Case> cases;
    util::Pcg32 rng(77);
    for (int i = 0; i < 1024; ++i) {
        Case c;
        c.light = i % int(lights.size());
        c.p = glm::vec3(4.0f * rng.nextFloat() - 2.0f, 2.0f * rng.nextFloat() - 1.0f,
                        4.0f * rng.nextFloat() - 2.0f);
        if (c.light == 6)
            c.p.y -= 6.0f; // far below the tiny rect: S < 1e-2 sr
        c.u1 = rng.nextFloat();
        c.u2 = rng.nextFloat();
        // Half the probes aim at the light (a CPU sample with other numbers), half anywhere.
        const float v1 = rng.nextFloat(), v2 = rng.nextFloat();
        LightSample aim = cpu[size_t(c.light)].sample(c.p, v1, v2);
        if (i % 2 == 0 && aim.valid) {
            c.probe = aim.wi;
        } else {
            float z = 2.0f * v1 - 1.0f, phi = 6.2831853f * v2, r = std::sqrt(1.0f - z * z);
            c.probe = glm::vec3(r * std::cos(phi), z, r * std::sin(phi));
        }
        cases.push_back(c);
    }
    std::vector<float> in;
    for (const Case& c : cases) {
        float v[12] = {c.p.x,     c.p.y, c.p.z,          c.u1, c.probe.x, c.probe.y,
                       c.probe.z, c.u2,  float(c.light), 0.0f, 0.0f,      0.0f};
        in.insert(in.end(), v, v + 12);
    }
    const uint32_t n = uint32_t(cases.size());
    std::vector<float> out(n * 16);
    {
        constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        auto lightBuf =
            vk::Buffer::create(**ctx, packed.size() * sizeof(GpuLight), kStorage, "lights");
        auto inBuf = vk::Buffer::create(**ctx, in.size() * 4, kStorage, "in");
        auto outBuf = vk::Buffer::create(**ctx, out.size() * 4, kStorage, "out");
        ASSERT_TRUE(lightBuf.ok() && inBuf.ok() && outBuf.ok());
        lightBuf->write(packed.data(), packed.size() * sizeof(GpuLight));
        inBuf->write(in.data(), in.size() * 4);
        auto kernel = vk::ComputeKernel::create(
            **ctx, {"lights twin",
                    *spirv,
                    {vk::BindingKind::StorageBuffer, vk::BindingKind::StorageBuffer,
                     vk::BindingKind::StorageBuffer},
                    4});
        ASSERT_TRUE(kernel.ok()) << kernel.error().message();
        kernel->bind(0, *lightBuf);
        kernel->bind(1, *inBuf);
        kernel->bind(2, *outBuf);
        auto runner = vk::CommandRunner::create(**ctx, "lights twin");
        ASSERT_TRUE(runner.ok());
        ASSERT_TRUE((*runner)
                        ->run([&](VkCommandBuffer cmd) {
                            kernel->dispatch(cmd, (n + 63) / 64, 1, 1, &n);
                            vk::computeToComputeAndHostBarrier(cmd);
                        })
                        .ok());
        outBuf->read(out.data(), out.size() * 4);
    }
    int validSamples = 0, hits = 0, flips = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const Case& c = cases[i];
        const LightSampler& light = cpu[size_t(c.light)];
        const float* o = &out[16 * i];
        SCOPED_TRACE("light " + std::to_string(c.light) + " case " + std::to_string(i));
        LightSample s = light.sample(c.p, c.u1, c.u2);
        ASSERT_EQ(s.valid, o[3] == 1.0f);
        if (s.valid) {
            ++validSamples;
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(o[k], s.wi[k], kTolerance);
                EXPECT_TRUE(near(o[4 + k], s.value[k])) << o[4 + k] << " vs " << s.value[k];
            }
            EXPECT_TRUE(near(o[7], s.pdf)) << o[7] << " vs " << s.pdf;
            EXPECT_EQ(o[9] == 1.0f, s.delta);
            if (std::isinf(s.distance))
                EXPECT_EQ(o[8], std::numeric_limits<float>::max());
            else
                EXPECT_TRUE(near(o[8], s.distance)) << o[8] << " vs " << s.distance;
        }
        // pdf and hit at the probe: support may differ only on a rim/edge, where rounding decides.
        auto hit = light.evalHit(c.p, c.probe);
        float pdf = light.pdf(c.p, c.probe);
        if (bool(hit) != (o[11] == 1.0f) || (pdf > 0.0f) != (o[10] > 0.0f)) {
            ++flips;
            continue;
        }
        EXPECT_TRUE(near(o[10], pdf)) << o[10] << " vs " << pdf;
        if (hit) {
            ++hits;
            if (std::isinf(hit->distance))
                EXPECT_EQ(o[12], std::numeric_limits<float>::max());
            else
                EXPECT_TRUE(near(o[12], hit->distance)) << o[12] << " vs " << hit->distance;
        }
    }
    std::printf("[ lights twin] %d valid samples, %d probe hits, %d rim flips of %u cases\n",
                validSamples, hits, flips, n);
    EXPECT_GT(validSamples, int(n) / 2);
    EXPECT_GT(hits, int(n) / 5);
    EXPECT_LE(flips, 2);
    EXPECT_EQ((*ctx)->validationMessageCount(), 0);
}

} // namespace
} // namespace wavelit::render
