// The whole vk layer on the real device (lavapipe in CI), validation on: context, buffers, a
// kernel with a push constant and two bindings, a round trip through the queue, and zero
// validation messages.
#include "vk/buffer.h"
#include "vk/command_runner.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"
#include "vk/shader_compiler.h"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

namespace wavelit::vk {
namespace {

const char* kSaxpy = R"(#version 460
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer X { float xs[]; };
layout(std430, binding = 1) buffer Y { float ys[]; };
layout(push_constant) uniform Push { float a; uint n; } pc;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < pc.n) ys[i] = pc.a * xs[i] + ys[i];
}
)";

std::unique_ptr<Context> makeContext() {
    auto ctx = Context::create({"", true});
    if (!ctx)
        ADD_FAILURE() << ctx.error().message();
    return ctx ? std::move(ctx.value()) : nullptr;
}

TEST(VkContext, CreatesDeviceWithValidationAndNoMessages) {
    auto ctx = makeContext();
    ASSERT_TRUE(ctx);
    EXPECT_FALSE(ctx->deviceName().empty());
    EXPECT_TRUE(ctx->validationEnabled());
    EXPECT_EQ(ctx->validationMessageCount(), 0);
}

TEST(VkContext, ValidationCallbackCountsMisuse) {
    // Proves the counter the other tests assert on is live: a zero-sized buffer is invalid
    // usage (VUID-VkBufferCreateInfo-size-00912) that the layer must report.
    auto ctx = makeContext();
    ASSERT_TRUE(ctx);
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = 0;
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    std::printf("(one validation error about a zero-sized buffer is expected below)\n");
    std::fflush(stdout);
    VkResult result = vkCreateBuffer(ctx->device(), &info, nullptr, &buffer);
    if (result == VK_SUCCESS && buffer != VK_NULL_HANDLE)
        vkDestroyBuffer(ctx->device(), buffer, nullptr);
    EXPECT_GE(ctx->validationMessageCount(), 1);
}

TEST(VkContext, UnknownDeviceNameIsAnErrorListingDevices) {
    auto ctx = Context::create({"no-such-gpu-xyz", false});
    ASSERT_FALSE(ctx.ok());
    EXPECT_NE(ctx.error().message().find("no-such-gpu-xyz"), std::string::npos);
    EXPECT_NE(ctx.error().message().find("available"), std::string::npos);
}

TEST(VkContext, SelectsByIndexAndByNameSubstring) {
    auto devices = Context::listDevices();
    ASSERT_TRUE(devices.ok()) << devices.error().message();
    ASSERT_FALSE(devices->empty());
    auto byIndex = Context::create({"0", false});
    ASSERT_TRUE(byIndex.ok()) << byIndex.error().message();
    EXPECT_EQ((*byIndex)->deviceName(), devices->front().name);
    std::string part = devices->front().name.substr(0, 4);
    auto byName = Context::create({part, false});
    ASSERT_TRUE(byName.ok()) << byName.error().message();
    EXPECT_NE((*byName)->deviceName().find(part), std::string::npos);
}

TEST(VkComputeKernel, SaxpyRoundTripHasNoValidationMessages) {
    auto ctx = makeContext();
    ASSERT_TRUE(ctx);
    constexpr uint32_t n = 1000;
    std::vector<float> x(n), y(n);
    std::iota(x.begin(), x.end(), 0.0f);
    std::fill(y.begin(), y.end(), 1.0f);
    {
        auto spirv = compileComputeShader(kSaxpy, "saxpy.comp", {});
        ASSERT_TRUE(spirv.ok()) << spirv.error().message();
        auto xb = Buffer::create(*ctx, n * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "x");
        auto yb = Buffer::create(*ctx, n * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "y");
        ASSERT_TRUE(xb.ok() && yb.ok());
        xb->write(x.data(), n * 4);
        yb->write(y.data(), n * 4);
        auto kernel = ComputeKernel::create(
            *ctx, {"saxpy", *spirv, {BindingKind::StorageBuffer, BindingKind::StorageBuffer}, 8});
        ASSERT_TRUE(kernel.ok()) << kernel.error().message();
        kernel->bind(0, *xb);
        kernel->bind(1, *yb);
        auto runner = CommandRunner::create(*ctx, "saxpy");
        ASSERT_TRUE(runner.ok()) << runner.error().message();
        struct {
            float a;
            uint32_t n;
        } push{3.0f, n};
        for (int pass = 0; pass < 2; ++pass) {
            auto status = (*runner)->run([&](VkCommandBuffer cmd) {
                kernel->dispatch(cmd, (n + 63) / 64, 1, 1, &push);
                computeToComputeAndHostBarrier(cmd);
            });
            ASSERT_TRUE(status.ok()) << status.error().message();
        }
        std::vector<float> out(n);
        yb->read(out.data(), n * 4);
        for (uint32_t i = 0; i < n; ++i)
            ASSERT_EQ(out[i], 1.0f + 2.0f * 3.0f * float(i)) << i;
    }
    EXPECT_EQ(ctx->validationMessageCount(), 0);
}

} // namespace
} // namespace wavelit::vk
