// Limits said up front (render_limits.h): the plan check names what is too big, by how much, and
// what to do; a render size beyond lavapipe's storage-buffer range is refused by RenderSession
// before anything is allocated.
#include "render/gpu/render_limits.h"

#include "render/session/render_session.h"
#include "scene/scene_io.h"
#include "util/timer.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace wavelit::render {
namespace {

// lavapipe (Mesa 22.3): 128 MiB storage buffers, a 2 GiB heap, 65535 workgroups a dimension.
GpuDeviceLimits lavapipeLimits() {
    GpuDeviceLimits l;
    l.deviceName = "llvmpipe (test)";
    l.maxStorageBufferRange = 128u << 20;
    l.memoryHeapBytes = uint64_t(2) << 30;
    l.maxWorkGroupCount[0] = l.maxWorkGroupCount[1] = 65535;
    return l;
}

GpuMemoryPlan planOfSize(int width, int height) {
    GpuMemoryPlan plan;
    plan.width = width;
    plan.height = height;
    plan.buffers.push_back(gpuAccumulationPlan(width, height));
    return plan;
}

void expectContains(const std::string& text, const std::string& needle) {
    EXPECT_NE(text.find(needle), std::string::npos) << "'" << needle << "' not in: " << text;
}

TEST(RenderLimits, AccumulationIsSixteenBytesAPixel) {
    const GpuBufferPlan a = gpuAccumulationPlan(640, 480);
    EXPECT_EQ(a.name, "accumulation");
    EXPECT_EQ(a.bytes, uint64_t(640) * 480 * 16);
    EXPECT_EQ(a.count, uint64_t(640) * 480);
}

TEST(RenderLimits, OversizedRenderNamesSizeLimitExcessAndRemedy) {
    auto status = checkGpuMemoryPlan(planOfSize(16384, 16384), lavapipeLimits());
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().kind, util::ErrorKind::Invalid);
    EXPECT_TRUE(status.error().file.empty());
    const std::string m = status.error().message();
    expectContains(m, "the render size 16384x16384 is too big for llvmpipe (test)");
    expectContains(m, "accumulation buffer needs 4096.0 MiB (268435456 pixels)");
    expectContains(m, "3968.0 MiB more than the device's storage-buffer limit of 128.0 MiB");
    expectContains(m, "maxStorageBufferRange");
    expectContains(m, "render at a smaller size: at most 8388608 pixels fit, e.g. 2896x2896");
}

TEST(RenderLimits, SuggestedSizeKeepsTheAspectRatioAndFits) {
    auto status = checkGpuMemoryPlan(planOfSize(16000, 9000), lavapipeLimits());
    ASSERT_FALSE(status.ok());
    // sqrt(8388608 / 144e6) = 0.24136: 3861 x 2172 = 8386092 pixels.
    expectContains(status.error().message(), "e.g. 3861x2172");
    EXPECT_TRUE(checkGpuMemoryPlan(planOfSize(3861, 2172), lavapipeLimits()).ok());
}

TEST(RenderLimits, ExactlyTheStorageRangeFits) {
    EXPECT_TRUE(checkGpuMemoryPlan(planOfSize(4096, 2048), lavapipeLimits()).ok()); // 128 MiB
    EXPECT_FALSE(checkGpuMemoryPlan(planOfSize(4096, 2049), lavapipeLimits()).ok());
}

TEST(RenderLimits, TooManyTrianglesNamesTheMeshesAndHowManyFit) {
    GpuMemoryPlan plan = planOfSize(512, 512);
    const uint64_t triangles = 2'000'000;
    plan.buffers.push_back({"bvh triangles", triangles * 96, triangles, "triangles",
                            "the scene's meshes (2000000 triangles)",
                            "use fewer triangles (simpler or fewer meshes)"});
    auto status = checkGpuMemoryPlan(plan, lavapipeLimits());
    ASSERT_FALSE(status.ok());
    const std::string m = status.error().message();
    expectContains(m, "the scene's meshes (2000000 triangles) is too big");
    expectContains(m, "bvh triangles buffer needs 183.1 MiB");
    expectContains(m, "55.1 MiB more than the device's storage-buffer limit of 128.0 MiB");
    expectContains(m, "use fewer triangles (simpler or fewer meshes): at most 1398101 triangles fit");
}

TEST(RenderLimits, TotalBeyondTheHeapNamesTheLargestBuffers) {
    GpuDeviceLimits limits = lavapipeLimits();
    limits.memoryHeapBytes = 200u << 20;
    GpuMemoryPlan plan = planOfSize(2048, 2048); // 64 MiB
    plan.buffers.push_back({"environment", 100u << 20, 0, "", "the environment map (a)",
                            "use a smaller environment map"});
    plan.buffers.push_back({"env sampling table", 50u << 20, 0, "", "the table",
                            "use a smaller environment map"});
    auto status = checkGpuMemoryPlan(plan, limits);
    ASSERT_FALSE(status.ok());
    const std::string m = status.error().message();
    expectContains(m, "the render needs 214.0 MiB of device memory in all, 14.0 MiB more than "
                      "llvmpipe (test)'s memory heap of 200.0 MiB");
    expectContains(m, "environment 100.0 MiB, accumulation 64.0 MiB, env sampling table 50.0 MiB");
    expectContains(m, "use a smaller environment map, or render at a smaller size");
}

TEST(RenderLimits, WorkgroupCountLimitsTheWidth) {
    GpuDeviceLimits limits = lavapipeLimits();
    limits.maxStorageBufferRange = 0; // only the workgroups
    auto status = checkGpuMemoryPlan(planOfSize(600000, 1), limits);
    ASSERT_FALSE(status.ok());
    const std::string m = status.error().message();
    expectContains(m, "its width needs 75000 workgroups of 8 pixels, more than the device's limit "
                      "of 65535 (maxComputeWorkGroupCount); render at most 524280 pixels in width");
}

TEST(RenderLimits, CpuImageMemoryAgainstHalfThePhysicalMemory) {
    const uint64_t gib = uint64_t(1) << 30;
    EXPECT_TRUE(checkCpuImageMemory(1024, 1024, 16 * gib).ok());
    EXPECT_TRUE(checkCpuImageMemory(16384, 16384, 0).ok()); // unknown memory: unchecked
    auto status = checkCpuImageMemory(16384, 16384, 16 * gib); // 9 GiB > 8 GiB
    ASSERT_FALSE(status.ok());
    const std::string m = status.error().message();
    expectContains(m, "the render size 16384x16384 is too big for the CPU tracer");
    expectContains(m, "9216.0 MiB (36 bytes a pixel), 1024.0 MiB more than half of this "
                      "machine's 16384.0 MiB of memory");
    expectContains(m, "render at a smaller size");
}

TEST(RenderLimits, DeviceLossIsNamed) {
    const util::Error lost = util::makeError(
        util::ErrorKind::Device, "", "vkWaitForFences failed: VK_ERROR_DEVICE_LOST (-4)");
    const util::Error described = describePassError(lost, "llvmpipe (test)");
    EXPECT_EQ(described.kind, util::ErrorKind::Device);
    expectContains(described.message(),
                   "the Vulkan device was lost (VK_ERROR_DEVICE_LOST) while rendering on "
                   "llvmpipe (test): vkWaitForFences failed: VK_ERROR_DEVICE_LOST (-4)");
    const util::Error other =
        util::makeError(util::ErrorKind::Device, "", "vkQueueSubmit failed: VK_ERROR_OUT_OF_HOST_MEMORY");
    EXPECT_EQ(describePassError(other, "x").message(), other.message());
}

// End to end on the real device: refused with the storage-buffer limit before the pipeline is
// compiled or anything allocated (the error comes back in well under the pipeline's seconds).
TEST(RenderLimits, OversizedVulkanSessionIsRefusedUpFront) {
    const std::string path = std::string(WAVELIT_RESOURCE_DIR) + "/scenes/ring_on_ground.wlscene";
    if (!std::filesystem::exists(path))
        GTEST_SKIP() << path << " not present";
    auto scene = scene::loadScene(path);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    RenderOptions options;
    options.width = 16384;
    options.height = 16384;
    options.device = DeviceChoice::Vulkan;
    options.sampler = SamplerKind::Wavelet;
    options.validation = true;
    util::Timer timer;
    auto session = RenderSession::create(*scene, options);
    std::printf("refused in %.0f ms\n", timer.milliseconds());
    ASSERT_FALSE(session.ok());
    const std::string m = session.error().message();
    expectContains(m, "the render size 16384x16384 is too big for");
    expectContains(m, "maxStorageBufferRange");
    expectContains(m, "render at a smaller size");
}

} // namespace
} // namespace wavelit::render
