#include "vk/compute_kernel.h"

#include "util/check.h"
#include "util/timer.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/vk_error.h"

namespace wavelit::vk {
namespace {
VkDescriptorType descriptorType(BindingKind kind) {
    switch (kind) {
    case BindingKind::StorageBuffer: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case BindingKind::UniformBuffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case BindingKind::UniformTexelBuffer: return VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    }
    return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}
} // namespace

util::Result<ComputeKernel> ComputeKernel::create(const Context& ctx,
                                                  const ComputeKernelDesc& desc) {
    util::Timer timer;
    VkDevice dev = ctx.device();
    ComputeKernel k;
    k.m_device = dev;
    k.m_bindings = desc.bindings;
    k.m_pushBytes = desc.pushConstantBytes;

    VkShaderModuleCreateInfo moduleInfo{};
    moduleInfo.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    moduleInfo.codeSize = desc.spirv.size() * sizeof(uint32_t);
    moduleInfo.pCode = desc.spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    WAVELIT_VK_TRY(vkCreateShaderModule(dev, &moduleInfo, nullptr, &module),
                   "vkCreateShaderModule(" + desc.name + ")");
    k.m_module = ShaderModuleHandle(dev, module);
    ctx.setName(VK_OBJECT_TYPE_SHADER_MODULE, uint64_t(module), desc.name);

    k.m_views.resize(desc.bindings.size());
    k.m_maxTexels = ctx.limits().maxTexelBufferElements;
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    uint32_t counts[3] = {0, 0, 0}; // per BindingKind
    for (uint32_t i = 0; i < desc.bindings.size(); ++i) {
        VkDescriptorSetLayoutBinding b{};
        b.binding = i;
        b.descriptorType = descriptorType(desc.bindings[i]);
        b.descriptorCount = 1;
        b.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
        bindings.push_back(b);
        counts[size_t(desc.bindings[i])] += 1;
    }
    VkDescriptorSetLayoutCreateInfo setInfo{};
    setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    setInfo.bindingCount = uint32_t(bindings.size());
    setInfo.pBindings = bindings.data();
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    WAVELIT_VK_TRY(vkCreateDescriptorSetLayout(dev, &setInfo, nullptr, &setLayout),
                   "vkCreateDescriptorSetLayout(" + desc.name + ")");
    k.m_setLayout = DescriptorSetLayoutHandle(dev, setLayout);
    ctx.setName(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, uint64_t(setLayout), desc.name);

    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, desc.pushConstantBytes};
    VkPipelineLayoutCreateInfo layoutInfo{};
    layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout;
    layoutInfo.pushConstantRangeCount = desc.pushConstantBytes > 0 ? 1 : 0;
    layoutInfo.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    WAVELIT_VK_TRY(vkCreatePipelineLayout(dev, &layoutInfo, nullptr, &layout),
                   "vkCreatePipelineLayout(" + desc.name + ")");
    k.m_layout = PipelineLayoutHandle(dev, layout);
    ctx.setName(VK_OBJECT_TYPE_PIPELINE_LAYOUT, uint64_t(layout), desc.name);

    VkComputePipelineCreateInfo pipeInfo{};
    pipeInfo.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    pipeInfo.flags = VK_PIPELINE_CREATE_DISPATCH_BASE_BIT; // dispatchRegions (Vulkan 1.1 core)
    pipeInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    pipeInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipeInfo.stage.module = module;
    pipeInfo.stage.pName = "main";
    pipeInfo.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    WAVELIT_VK_TRY(vkCreateComputePipelines(dev, VK_NULL_HANDLE, 1, &pipeInfo, nullptr, &pipeline),
                   "vkCreateComputePipelines(" + desc.name + ")");
    k.m_pipeline = PipelineHandle(dev, pipeline);
    ctx.setName(VK_OBJECT_TYPE_PIPELINE, uint64_t(pipeline), desc.name);

    std::vector<VkDescriptorPoolSize> sizes;
    for (BindingKind kind : {BindingKind::StorageBuffer, BindingKind::UniformBuffer,
                             BindingKind::UniformTexelBuffer})
        if (counts[size_t(kind)])
            sizes.push_back({descriptorType(kind), counts[size_t(kind)]});
    VkDescriptorPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = uint32_t(sizes.size());
    poolInfo.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    WAVELIT_VK_TRY(vkCreateDescriptorPool(dev, &poolInfo, nullptr, &pool),
                   "vkCreateDescriptorPool(" + desc.name + ")");
    k.m_pool = DescriptorPoolHandle(dev, pool);
    ctx.setName(VK_OBJECT_TYPE_DESCRIPTOR_POOL, uint64_t(pool), desc.name);

    VkDescriptorSetAllocateInfo allocInfo{};
    allocInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    allocInfo.descriptorPool = pool;
    allocInfo.descriptorSetCount = 1;
    allocInfo.pSetLayouts = &setLayout;
    WAVELIT_VK_TRY(vkAllocateDescriptorSets(dev, &allocInfo, &k.m_set),
                   "vkAllocateDescriptorSets(" + desc.name + ")");
    ctx.setName(VK_OBJECT_TYPE_DESCRIPTOR_SET, uint64_t(k.m_set), desc.name);
    k.m_creationSeconds = timer.seconds();
    return k;
}

void ComputeKernel::bind(uint32_t binding, const Buffer& buffer) {
    WAVELIT_CHECK(binding < m_bindings.size() &&
                  m_bindings[binding] != BindingKind::UniformTexelBuffer);
    VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = m_set;
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = descriptorType(m_bindings[binding]);
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(m_device, 1, &write, 0, nullptr);
}

uint32_t ComputeKernel::texelBytes(VkFormat format) {
    switch (format) {
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_R32_SFLOAT: return 4;
    case VK_FORMAT_R32G32_UINT:
    case VK_FORMAT_R32G32_SFLOAT: return 8;
    case VK_FORMAT_R32G32B32A32_UINT:
    case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
    default: return 0;
    }
}

util::Status ComputeKernel::bindTexels(uint32_t binding, const Buffer& buffer, VkFormat format) {
    const uint32_t bytes = texelBytes(format);
    WAVELIT_CHECK(binding < m_bindings.size() &&
                  m_bindings[binding] == BindingKind::UniformTexelBuffer && bytes > 0 &&
                  buffer.size() % bytes == 0);
    if (buffer.size() / bytes > m_maxTexels)
        return util::makeError(util::ErrorKind::Unsupported, "",
                               "a buffer of " + std::to_string(buffer.size()) + " bytes is " +
                                   std::to_string(buffer.size() / bytes) +
                                   " texels, more than the device's limit of " +
                                   std::to_string(m_maxTexels));
    VkBufferViewCreateInfo viewInfo{};
    viewInfo.sType = VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO;
    viewInfo.buffer = buffer.handle();
    viewInfo.format = format;
    viewInfo.offset = 0;
    viewInfo.range = VK_WHOLE_SIZE;
    VkBufferView view = VK_NULL_HANDLE;
    WAVELIT_VK_TRY(vkCreateBufferView(m_device, &viewInfo, nullptr, &view),
                   "vkCreateBufferView(binding " + std::to_string(binding) + ")");
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = m_set;
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    write.pTexelBufferView = &view;
    vkUpdateDescriptorSets(m_device, 1, &write, 0, nullptr);
    // The previous view goes only now that the set no longer names it.
    m_views[binding] = BufferViewHandle(m_device, view);
    return util::okStatus();
}

void ComputeKernel::bind(VkCommandBuffer cmd, const void* pushConstants) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipeline.get());
    VkDescriptorSet set = m_set;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout.get(), 0, 1, &set, 0,
                            nullptr);
    if (m_pushBytes > 0 && pushConstants)
        vkCmdPushConstants(cmd, m_layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, m_pushBytes,
                           pushConstants);
}

void ComputeKernel::dispatch(VkCommandBuffer cmd, uint32_t groupsX, uint32_t groupsY,
                             uint32_t groupsZ, const void* pushConstants) const {
    bind(cmd, pushConstants);
    vkCmdDispatch(cmd, groupsX, groupsY, groupsZ);
}

void ComputeKernel::dispatchRegions(VkCommandBuffer cmd, std::span<const DispatchRegion> regions,
                                    const void* pushConstants) const {
    bind(cmd, pushConstants);
    for (const DispatchRegion& r : regions)
        if (r.groupsX > 0 && r.groupsY > 0)
            vkCmdDispatchBase(cmd, r.baseX, r.baseY, 0, r.groupsX, r.groupsY, 1);
}

} // namespace wavelit::vk
