#include "vk/command_runner.h"

#include "vk/context.h"
#include "vk/vk_error.h"

#include <cstdint>

namespace wavelit::vk {

util::Result<std::unique_ptr<CommandRunner>> CommandRunner::create(const Context& ctx,
                                                                   const std::string& debugName) {
    std::unique_ptr<CommandRunner> r(new CommandRunner());
    r->m_device = ctx.device();
    r->m_queue = ctx.queue();
    VkCommandPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = ctx.queueFamily();
    VkCommandPool pool = VK_NULL_HANDLE;
    WAVELIT_VK_TRY(vkCreateCommandPool(ctx.device(), &poolInfo, nullptr, &pool),
                   "vkCreateCommandPool(" + debugName + ")");
    r->m_pool = CommandPoolHandle(ctx.device(), pool);
    ctx.setName(VK_OBJECT_TYPE_COMMAND_POOL, uint64_t(pool), debugName);

    VkCommandBufferAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    WAVELIT_VK_TRY(vkAllocateCommandBuffers(ctx.device(), &alloc, &r->m_cmd),
                   "vkAllocateCommandBuffers(" + debugName + ")");
    ctx.setName(VK_OBJECT_TYPE_COMMAND_BUFFER, uint64_t(r->m_cmd), debugName);

    VkFenceCreateInfo fenceInfo{};
    fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    VkFence fence = VK_NULL_HANDLE;
    WAVELIT_VK_TRY(vkCreateFence(ctx.device(), &fenceInfo, nullptr, &fence),
                   "vkCreateFence(" + debugName + ")");
    r->m_fence = FenceHandle(ctx.device(), fence);
    ctx.setName(VK_OBJECT_TYPE_FENCE, uint64_t(fence), debugName);
    return r;
}

CommandRunner::~CommandRunner() {
    if (m_pending) {
        VkFence fence = m_fence.get();
        vkWaitForFences(m_device, 1, &fence, VK_TRUE, UINT64_MAX);
    }
}

util::Status CommandRunner::run(const std::function<void(VkCommandBuffer)>& record) {
    VkFence fence = m_fence.get();
    WAVELIT_VK_TRY(vkResetFences(m_device, 1, &fence), "vkResetFences");
    WAVELIT_VK_TRY(vkResetCommandBuffer(m_cmd, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    WAVELIT_VK_TRY(vkBeginCommandBuffer(m_cmd, &begin), "vkBeginCommandBuffer");
    record(m_cmd);
    WAVELIT_VK_TRY(vkEndCommandBuffer(m_cmd), "vkEndCommandBuffer");
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &m_cmd;
    WAVELIT_VK_TRY(vkQueueSubmit(m_queue, 1, &submit, fence), "vkQueueSubmit");
    m_pending = true;
    WAVELIT_VK_TRY(vkWaitForFences(m_device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    m_pending = false;
    return util::okStatus();
}

void computeToComputeAndHostBarrier(VkCommandBuffer cmd) {
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask =
        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &barrier, 0, nullptr, 0, nullptr);
}

} // namespace wavelit::vk
