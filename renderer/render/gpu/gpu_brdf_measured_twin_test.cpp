// `measured`'s GLSL twin (plugins/measured.glsl) against its C++ plugin (plugins/measured.cpp,
// brdf_table.cpp), through the table buffer the path tracer binds (gpu_brdf_tables.h): 10^4
// random (wo, wi) pairs through eval, pdf and sample on the Vulkan device (issue 16: ≤ 1e-4
// relative), on two tables packed together so that a non-zero offset is exercised: the shipped
// example (glossy r = 0.5, 24 x 64 x 32) and a small phong r = 0.3 table (8 x 16 x 12) whose
// bins are wide, so most pairs interpolate across bins far from their centres.
#include "plugins/brdf.h"
#include "plugins/brdf_table.h"
#include "render/gpu/brdf_shader_source.h"
#include "render/gpu/gpu_brdf_tables.h"
#include "render/gpu/gpu_path_tracer.h"
#include "render/testing/brdf_twin_kernel.h"
#include "render/gpu/gpu_scene_data.h"
#include "util/rng.h"
#include "vk/buffer.h"
#include "vk/command_runner.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace wavelit::render {
namespace {

// The kernel: render/testing/brdf_twin_kernel.h (the roughness slot holds the table offset;
// the tables sit at binding 2).

constexpr float kRelTolerance = 1e-4f; // issue 16
constexpr int kPairs = 10'000;

std::shared_ptr<const plugins::BrdfTable> loadTable(const std::string& path) {
    auto t = plugins::loadMerlBrdf(path);
    EXPECT_TRUE(t.ok()) << (t.ok() ? "" : t.error().message());
    return t.ok() ? *t : nullptr;
}

std::shared_ptr<const plugins::BrdfTable> smallPhongTable() {
    const std::vector<char> bytes = plugins::tabulateMerlBrdf(
        *plugins::findBrdf("phong"), plugins::BrdfParams(glm::vec3(0.9f, 0.5f, 0.2f), 0.3f), 8, 16, 12);
    const std::string path = (std::filesystem::temp_directory_path() / "wavelit_twin_phong.binary").string();
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    auto t = loadTable(path);
    std::filesystem::remove(path);
    return t;
}

// |a − b| relative to |b|, or absolute below 1e-3 (where a relative error means nothing).
float relativeError(float a, float b) { return std::abs(a - b) / std::max(std::abs(b), 1e-3f); }

TEST(GpuBrdfTwin, MeasuredGlslMatchesCppThroughTheTableBuffer) {
    auto ctx = vk::Context::create({"", true});
    ASSERT_TRUE(ctx.ok()) << ctx.error().message();
    vk::ShaderCompileOptions options{{gpuShaderDirectory(), gpuPluginDirectory()},
                                     {std::string(kBrdfTableBindingDefine) + "=2"}};
    auto spirv = compileWithBrdfDispatch(kBrdfTwinKernel, "brdf_measured_twin_test.comp", options);
    ASSERT_TRUE(spirv.ok()) << spirv.error().message();

    scene::Scene scene;
    for (auto table : {loadTable(std::string(WAVELIT_RESOURCE_DIR) + "/brdfs/glossy-copper-r05.binary"),
                       smallPhongTable()}) {
        ASSERT_TRUE(table);
        scene::Material m;
        m.brdf = "measured";
        m.brdfTable = table;
        scene.materials.push_back(m);
    }
    auto packed = packGpuBrdfTables(scene);
    ASSERT_TRUE(packed.ok()) << packed.error().message();
    const plugins::Brdf& measured = *plugins::findBrdf("measured");
    const uint32_t type = gpuBrdfType(measured);

    struct Case {
        plugins::BrdfParams params;
        float offset;
        glm::vec3 wo, probe;
        float u1, u2;
    };
    std::vector<Case> cases;
    util::Pcg32 rng(16);
    for (int i = 0; i < kPairs; ++i) {
        const scene::Material& m = scene.materials[size_t(i % 2)];
        // Views up to grazing (85-89 degrees every 16th pair), probes over the whole hemisphere.
        const float cosO = i % 16 == 3 ? 0.0175f + 0.07f * rng.nextFloat() : 0.02f + 0.98f * rng.nextFloat();
        const float phi = 6.2831853f * rng.nextFloat(), sinO = std::sqrt(1.0f - cosO * cosO);
        const glm::vec3 wo(sinO * std::cos(phi), sinO * std::sin(phi), cosO);
        // Every 8th probe is near the mirror direction (the peak), the rest uniform on the disk.
        glm::vec3 probe;
        if (i % 8 == 5) {
            probe = glm::normalize(glm::vec3(-wo.x, -wo.y, wo.z) +
                                   0.05f * glm::vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 0.0f));
            // z as the kernel rebuilds it from x and y, so both sides evaluate one direction.
            probe.z = std::sqrt(std::max(0.0f, 1.0f - probe.x * probe.x - probe.y * probe.y));
        } else {
            const float pr = 0.99f * std::sqrt(rng.nextFloat()), pphi = 6.2831853f * rng.nextFloat();
            probe = glm::vec3(pr * std::cos(pphi), pr * std::sin(pphi), 0.0f);
            probe.z = std::sqrt(std::max(0.0f, 1.0f - probe.x * probe.x - probe.y * probe.y));
        }
        const plugins::BrdfParams p(glm::vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()), 0.5f, 0.0f,
                                    m.brdfTable);
        cases.push_back({p, float(packed->offsetOf.at(m.brdfTable.get())), wo, probe, rng.nextFloat(),
                         rng.nextFloat()});
    }
    EXPECT_GT(cases[1].offset, 0.0f); // the second table really is at an offset
    std::vector<float> in;
    for (const Case& c : cases) {
        const float v[12] = {c.wo.x, c.wo.y, c.wo.z, c.u1, c.params.baseColor.r, c.params.baseColor.g,
                             c.params.baseColor.b, c.offset, c.u2, float(type), c.probe.x, c.probe.y};
        in.insert(in.end(), v, v + 12);
    }
    const uint32_t n = uint32_t(cases.size());
    std::vector<float> out(n * 12);
    {
        constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        auto inBuf = vk::Buffer::create(**ctx, in.size() * 4, kStorage, "in");
        auto outBuf = vk::Buffer::create(**ctx, out.size() * 4, kStorage, "out");
        auto tableBuf = vk::Buffer::create(**ctx, packed->floats.size() * 4, kStorage, "tables");
        ASSERT_TRUE(inBuf.ok() && outBuf.ok() && tableBuf.ok());
        inBuf->write(in.data(), in.size() * 4);
        tableBuf->write(packed->floats.data(), packed->floats.size() * 4);
        auto kernel = vk::ComputeKernel::create(
            **ctx, {"measured twin", *spirv, std::vector<vk::BindingKind>(3, vk::BindingKind::StorageBuffer), 4});
        ASSERT_TRUE(kernel.ok()) << kernel.error().message();
        kernel->bind(0, *inBuf);
        kernel->bind(1, *outBuf);
        kernel->bind(2, *tableBuf);
        auto runner = vk::CommandRunner::create(**ctx, "measured twin");
        ASSERT_TRUE(runner.ok());
        ASSERT_TRUE((*runner)
                        ->run([&](VkCommandBuffer cmd) {
                            kernel->dispatch(cmd, (n + 63) / 64, 1, 1, &n);
                            vk::computeToComputeAndHostBarrier(cmd);
                        })
                        .ok());
        outBuf->read(out.data(), out.size() * 4);
    }
    float worstEval = 0.0f, worstSample = 0.0f;
    int valid = 0, nonZero = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const Case& c = cases[i];
        const float* o = &out[12 * i];
        SCOPED_TRACE("case " + std::to_string(i));
        const glm::vec3 fe = measured.eval(c.params, c.wo, c.probe);
        for (int k = 0; k < 3; ++k) {
            EXPECT_LE(relativeError(o[8 + k], fe[k]), kRelTolerance) << o[8 + k] << " vs " << fe[k];
            worstEval = std::max(worstEval, relativeError(o[8 + k], fe[k]));
        }
        nonZero += fe.r > 1e-3f;
        const float pe = measured.pdf(c.params, c.wo, c.probe);
        EXPECT_LE(relativeError(o[11], pe), kRelTolerance) << o[11] << " vs " << pe;
        const plugins::BrdfSample s = measured.sample(c.params, c.wo, c.u1, c.u2);
        ASSERT_EQ(s.valid, o[3] == 1.0f);
        if (!s.valid) continue;
        ++valid;
        // The same cosine-weighted direction (float sin/cos on each side), then f and pdf there.
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(o[k], s.wi[k], 1e-5f);
        const glm::vec3 fs = measured.eval(c.params, c.wo, glm::vec3(o[0], o[1], o[2]));
        for (int k = 0; k < 3; ++k) {
            EXPECT_LE(relativeError(o[4 + k], fs[k]), kRelTolerance) << o[4 + k] << " vs " << fs[k];
            worstSample = std::max(worstSample, relativeError(o[4 + k], fs[k]));
        }
        EXPECT_LE(relativeError(o[7], measured.pdf(c.params, c.wo, glm::vec3(o[0], o[1], o[2]))), kRelTolerance);
    }
    EXPECT_GT(valid, int(n) * 9 / 10);
    EXPECT_GT(nonZero, int(n) / 2);
    std::printf("[measured twin] %u pairs, %d valid samples; worst relative error eval %.2e, sampled f %.2e\n", n,
                valid, double(worstEval), double(worstSample));
    EXPECT_EQ((*ctx)->validationMessageCount(), 0);
}

} // namespace
} // namespace wavelit::render
