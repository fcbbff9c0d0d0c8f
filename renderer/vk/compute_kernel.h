// A compute pipeline with one descriptor set of buffers and an optional push-constant block:
// shader module, set layout, pipeline layout, pipeline, descriptor pool and set, owned together
// because none of them is useful alone. Created once (LLVM compiles the pipeline at creation on
// lavapipe, which takes a while: creationSeconds() reports it) and dispatched every pass.
#pragma once

#include "util/result.h"
#include "vk/handle.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace wavelit::vk {

class Buffer;
class Context;

// UniformTexelBuffer: the buffer seen as texels (a `samplerBuffer` read with texelFetch; the
// buffer needs VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT). lavapipe reads texels through its
// texture path, a gather in registers, where an SSBO read is a loop over the lanes
// (docs/performance.md "Texel buffers").
enum class BindingKind { StorageBuffer, UniformBuffer, UniformTexelBuffer };

// A rectangle of workgroups [baseX, baseX + groupsX) x [baseY, baseY + groupsY) (z: one layer).
struct DispatchRegion {
    uint32_t baseX = 0, baseY = 0, groupsX = 0, groupsY = 0;
};

struct ComputeKernelDesc {
    std::string name; // debug name of every object
    std::vector<uint32_t> spirv;
    std::vector<BindingKind> bindings; // binding i of set 0
    uint32_t pushConstantBytes = 0;
};

class ComputeKernel {
public:
    static util::Result<ComputeKernel> create(const Context& ctx, const ComputeKernelDesc& desc);
    ComputeKernel() = default;
    ComputeKernel(ComputeKernel&&) noexcept = default;
    ComputeKernel& operator=(ComputeKernel&&) noexcept = default;

    // Points binding i at the whole buffer. Must not be called while a dispatch is in flight.
    void bind(uint32_t binding, const Buffer& buffer);
    // Points texel binding i at a view of the whole buffer as `format` texels (R32, RG32 or
    // RGBA32, UINT or SFLOAT; made here, kept until the next call for i). The buffer's size is a
    // multiple of the texel's; more texels than the device's maxTexelBufferElements is an
    // Unsupported error. Same rule.
    util::Status bindTexels(uint32_t binding, const Buffer& buffer, VkFormat format);
    // Bytes of a texel of `format`, for the formats bindTexels takes (else 0).
    static uint32_t texelBytes(VkFormat format);
    // Records bind + push constants + dispatch into cmd.
    void dispatch(VkCommandBuffer cmd, uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ,
                  const void* pushConstants = nullptr) const;
    // Records bind + push constants + one vkCmdDispatchBase per region: gl_WorkGroupID and
    // gl_GlobalInvocationID include the region's base, so a shader that indexes by them covers
    // part of the full grid unchanged (a pass split into pieces that can be submitted apart).
    void dispatchRegions(VkCommandBuffer cmd, std::span<const DispatchRegion> regions,
                         const void* pushConstants = nullptr) const;
    double creationSeconds() const { return m_creationSeconds; }

private:
    // Binds the pipeline and the descriptor set and pushes the constants (both dispatch forms).
    void bind(VkCommandBuffer cmd, const void* pushConstants) const;

    // Declaration order = reverse destruction order: pipeline and layouts go before the pool.
    VkDevice m_device = VK_NULL_HANDLE;
    std::vector<BindingKind> m_bindings;
    std::vector<BufferViewHandle> m_views; // per binding; only texel bindings hold one
    uint64_t m_maxTexels = 0;              // the device's maxTexelBufferElements
    uint32_t m_pushBytes = 0;
    DescriptorPoolHandle m_pool;
    DescriptorSetLayoutHandle m_setLayout;
    PipelineLayoutHandle m_layout;
    ShaderModuleHandle m_module;
    PipelineHandle m_pipeline;
    VkDescriptorSet m_set = VK_NULL_HANDLE; // freed with m_pool
    double m_creationSeconds = 0.0;
};

} // namespace wavelit::vk
