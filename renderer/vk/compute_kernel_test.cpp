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

// One buffer of words read through three texel views (R32UI, RG32UI, RGBA32UI) gives back the
// same words; binding a second buffer replaces the views (the first view's buffer is then
// destroyed while the kernel lives: its view must be gone with the rebind).
const char* kTexelCopy = R"(#version 460
layout(local_size_x = 64) in;
layout(binding = 0) uniform usamplerBuffer words;
layout(binding = 1) uniform usamplerBuffer pairs;
layout(binding = 2) uniform usamplerBuffer quads;
layout(std430, binding = 3) buffer Out { uint outs[]; };
layout(push_constant) uniform Push { uint n; } pc;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.n) return;
    outs[3u * i] = texelFetch(words, int(i)).x;
    outs[3u * i + 1u] = texelFetch(pairs, int(i / 2u))[i % 2u];
    outs[3u * i + 2u] = texelFetch(quads, int(i / 4u))[i % 4u];
}
)";

TEST(VkComputeKernel, TexelViewsReadTheBufferWordsAndFollowARebind) {
    auto ctx = makeContext();
    ASSERT_TRUE(ctx);
    constexpr uint32_t n = 1024;
    {
        auto spirv = compileComputeShader(kTexelCopy, "texel_copy.comp", {});
        ASSERT_TRUE(spirv.ok()) << spirv.error().message();
        constexpr VkBufferUsageFlags kTexels =
            VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        auto out = Buffer::create(*ctx, 3 * n * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "out");
        ASSERT_TRUE(out.ok());
        auto kernel = ComputeKernel::create(
            *ctx, {"texel_copy", *spirv,
                   {BindingKind::UniformTexelBuffer, BindingKind::UniformTexelBuffer,
                    BindingKind::UniformTexelBuffer, BindingKind::StorageBuffer},
                   4});
        ASSERT_TRUE(kernel.ok()) << kernel.error().message();
        kernel->bind(3, *out);
        auto runner = CommandRunner::create(*ctx, "texel copy");
        ASSERT_TRUE(runner.ok()) << runner.error().message();
        for (uint32_t round = 0; round < 2; ++round) {
            std::vector<uint32_t> words(n);
            for (uint32_t i = 0; i < n; ++i)
                words[i] = 0x9E3779B9u * (i + 1u) ^ (round << 31);
            auto in = Buffer::create(*ctx, n * 4, kTexels, "in");
            ASSERT_TRUE(in.ok());
            in->write(words.data(), n * 4);
            ASSERT_TRUE(kernel->bindTexels(0, *in, VK_FORMAT_R32_UINT).ok());
            ASSERT_TRUE(kernel->bindTexels(1, *in, VK_FORMAT_R32G32_UINT).ok());
            ASSERT_TRUE(kernel->bindTexels(2, *in, VK_FORMAT_R32G32B32A32_UINT).ok());
            uint32_t push = n;
            auto status = (*runner)->run([&](VkCommandBuffer cmd) {
                kernel->dispatch(cmd, n / 64, 1, 1, &push);
                computeToComputeAndHostBarrier(cmd);
            });
            ASSERT_TRUE(status.ok()) << status.error().message();
            std::vector<uint32_t> got(3 * n);
            out->read(got.data(), got.size() * 4);
            for (uint32_t i = 0; i < n; ++i)
                for (uint32_t view = 0; view < 3; ++view)
                    ASSERT_EQ(got[3 * i + view], words[i]) << "round " << round << " view " << view;
            // `in` goes here, before the next round binds its successor.
        }
    }
    EXPECT_EQ(ComputeKernel::texelBytes(VK_FORMAT_R32_SFLOAT), 4u);
    EXPECT_EQ(ComputeKernel::texelBytes(VK_FORMAT_R32G32B32A32_UINT), 16u);
    EXPECT_EQ(ComputeKernel::texelBytes(VK_FORMAT_R8_UNORM), 0u);
    EXPECT_EQ(ctx->validationMessageCount(), 0);
}

} // namespace
} // namespace wavelit::vk
