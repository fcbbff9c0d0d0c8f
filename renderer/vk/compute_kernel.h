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

enum class BindingKind { StorageBuffer, UniformBuffer };

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
