// Turning a failed VkResult into a util::Error that names the call that failed (architecture.md §9: check
// every VkResult). Device loss and out-of-memory become ErrorKind::Device so a render session can
// enter its error state instead of crashing.
#pragma once

#include "util/result.h"

#include <vulkan/vulkan.h>

#include <string>

namespace wavelit::vk {

const char* vkResultName(VkResult result);

// okStatus() for VK_SUCCESS, else a Device error "what failed: VK_ERROR_...".
util::Status vkCheck(VkResult result, const std::string& what);

} // namespace wavelit::vk

// Returns the error of a failed Vulkan call from a function returning Result<T> or Status.
#define WAVELIT_VK_TRY(call, what)                                                                 \
    do {                                                                                           \
        ::wavelit::util::Status wavelitVkStatus_ = ::wavelit::vk::vkCheck((call), (what));         \
        if (!wavelitVkStatus_)                                                                     \
            return wavelitVkStatus_.error();                                                       \
    } while (0)
