// One command pool, one primary command buffer and one fence on the Context's queue: record,
// submit, wait. A pass is synchronous inside this call so the caller (the editor's render
// thread, or the CLI) decides where the wait happens; the UI thread never calls it. The
// destructor waits for the last submit so nothing it used is freed while the device reads it.
#pragma once

#include "util/result.h"
#include "vk/handle.h"

#include <functional>
#include <memory>
#include <string>

namespace wavelit::vk {

class Context;

class CommandRunner {
public:
    static util::Result<std::unique_ptr<CommandRunner>> create(const Context& ctx,
                                                               const std::string& debugName);
    ~CommandRunner();
    CommandRunner(const CommandRunner&) = delete;
    CommandRunner& operator=(const CommandRunner&) = delete;

    // Records with `record`, submits, and waits for completion. A failed wait (device lost)
    // is returned as an ErrorKind::Device error.
    util::Status run(const std::function<void(VkCommandBuffer)>& record);

private:
    CommandRunner() = default;
    VkDevice m_device = VK_NULL_HANDLE;
    VkQueue m_queue = VK_NULL_HANDLE;
    CommandPoolHandle m_pool;
    FenceHandle m_fence;
    VkCommandBuffer m_cmd = VK_NULL_HANDLE; // freed with m_pool
    bool m_pending = false;
};

// A barrier making compute-shader writes visible to later compute reads and to the host.
void computeToComputeAndHostBarrier(VkCommandBuffer cmd);

} // namespace wavelit::vk
