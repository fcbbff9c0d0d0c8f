// Vulkan instance + physical/logical device + one compute queue. Device choice: an explicit index
// or case-insensitive name substring (ContextOptions::device, else env WAVELIT_VK_DEVICE), or by
// default a discrete GPU, then an integrated one, then anything else (lavapipe "llvmpipe").
//
// Validation (options.validation or env WAVELIT_VK_VALIDATION=1) enables
// VK_LAYER_KHRONOS_validation and a debug-utils messenger that logs and COUNTS every warning and
// error; tests assert the count stays 0. The Context is not movable (the messenger points at it)
// and must outlive every handle created on its device. Not thread-safe: one thread (the render
// thread) drives it.
#pragma once

#include "util/result.h"

#include <vulkan/vulkan.h>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

namespace wavelit::vk {

struct ContextOptions {
    std::string device; // index or name substring; empty: env WAVELIT_VK_DEVICE, else preference
    bool validation = false;
};

struct PhysicalDeviceInfo {
    uint32_t index = 0;
    std::string name;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
};

class Context {
public:
    // Errors: no Vulkan loader/driver, no matching device, device without int64 or compute.
    static util::Result<std::unique_ptr<Context>> create(const ContextOptions& options);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkDevice device() const { return m_device; }
    VkPhysicalDevice physicalDevice() const { return m_physical; }
    VkQueue queue() const { return m_queue; }
    uint32_t queueFamily() const { return m_queueFamily; }
    const std::string& deviceName() const { return m_deviceName; }
    // A CPU implementation (lavapipe): kernels may take another code shape there (its SIMD
    // lanes pay for every live value of a loop, a GPU for every extra copy of its code).
    bool cpuDevice() const { return m_cpuDevice; }
    const VkPhysicalDeviceLimits& limits() const { return m_limits; }
    // shaderFloat64 is enabled when the device has it (the direction samplers need it).
    bool hasFloat64() const { return m_float64; }
    bool validationEnabled() const { return m_messenger != VK_NULL_HANDLE; }
    // Warnings + errors reported by the validation layers since creation.
    int validationMessageCount() const { return m_validationMessages.load(); }

    // Memory type with all `required` property flags among `typeBits`; UINT32_MAX when none.
    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const;
    // Debug name shown in validation messages; a no-op without validation.
    void setName(VkObjectType type, uint64_t handle, const std::string& name) const;

    // Devices visible to the loader (for --device listings and error messages).
    static util::Result<std::vector<PhysicalDeviceInfo>> listDevices();

private:
    Context() = default;
    static VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(
        VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
        const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

    // Destroyed in reverse: device, messenger, instance (see ~Context).
    VkInstance m_instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT m_messenger = VK_NULL_HANDLE;
    VkPhysicalDevice m_physical = VK_NULL_HANDLE;
    VkDevice m_device = VK_NULL_HANDLE;
    VkQueue m_queue = VK_NULL_HANDLE;
    uint32_t m_queueFamily = 0;
    std::string m_deviceName;
    bool m_cpuDevice = false;
    VkPhysicalDeviceLimits m_limits{};
    bool m_float64 = false;
    VkPhysicalDeviceMemoryProperties m_memory{};
    PFN_vkSetDebugUtilsObjectNameEXT m_setObjectName = nullptr;
    std::atomic<int> m_validationMessages{0};
};

} // namespace wavelit::vk
