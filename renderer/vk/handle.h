// Move-only owners of device-level Vulkan handles: one type per handle kind (a Buffer handle can
// never be destroyed as an Image), no destroy() to remember. The owner keeps the VkDevice it was
// created on; the Context that owns the device must outlive every handle (members of a class are
// declared after its Context pointer and so destroyed first).
#pragma once

#include <vulkan/vulkan.h>

#include <utility>

namespace wavelit::vk {

template <typename T, void (*Destroy)(VkDevice, T, const VkAllocationCallbacks*)>
class DeviceHandle {
public:
    DeviceHandle() = default;
    DeviceHandle(VkDevice device, T handle) : m_device(device), m_handle(handle) {}
    ~DeviceHandle() { reset(); }
    DeviceHandle(const DeviceHandle&) = delete;
    DeviceHandle& operator=(const DeviceHandle&) = delete;
    DeviceHandle(DeviceHandle&& o) noexcept
        : m_device(o.m_device), m_handle(std::exchange(o.m_handle, VK_NULL_HANDLE)) {}
    DeviceHandle& operator=(DeviceHandle&& o) noexcept {
        if (this != &o) {
            reset();
            m_device = o.m_device;
            m_handle = std::exchange(o.m_handle, VK_NULL_HANDLE);
        }
        return *this;
    }

    T get() const { return m_handle; }
    explicit operator bool() const { return m_handle != VK_NULL_HANDLE; }
    void reset() {
        if (m_handle != VK_NULL_HANDLE)
            Destroy(m_device, m_handle, nullptr);
        m_handle = VK_NULL_HANDLE;
    }

private:
    VkDevice m_device = VK_NULL_HANDLE;
    T m_handle = VK_NULL_HANDLE;
};

// vkDestroy* and vkFreeMemory have the same shape; the wrappers below give every kind its type.
inline void destroyBuffer(VkDevice d, VkBuffer h, const VkAllocationCallbacks* a) {
    vkDestroyBuffer(d, h, a);
}
inline void freeMemory(VkDevice d, VkDeviceMemory h, const VkAllocationCallbacks* a) {
    vkFreeMemory(d, h, a);
}
inline void destroyShaderModule(VkDevice d, VkShaderModule h, const VkAllocationCallbacks* a) {
    vkDestroyShaderModule(d, h, a);
}
inline void destroyDescriptorSetLayout(VkDevice d, VkDescriptorSetLayout h,
                                       const VkAllocationCallbacks* a) {
    vkDestroyDescriptorSetLayout(d, h, a);
}
inline void destroyDescriptorPool(VkDevice d, VkDescriptorPool h, const VkAllocationCallbacks* a) {
    vkDestroyDescriptorPool(d, h, a);
}
inline void destroyPipelineLayout(VkDevice d, VkPipelineLayout h, const VkAllocationCallbacks* a) {
    vkDestroyPipelineLayout(d, h, a);
}
inline void destroyPipeline(VkDevice d, VkPipeline h, const VkAllocationCallbacks* a) {
    vkDestroyPipeline(d, h, a);
}
inline void destroyCommandPool(VkDevice d, VkCommandPool h, const VkAllocationCallbacks* a) {
    vkDestroyCommandPool(d, h, a);
}
inline void destroyFence(VkDevice d, VkFence h, const VkAllocationCallbacks* a) {
    vkDestroyFence(d, h, a);
}
inline void destroyBufferView(VkDevice d, VkBufferView h, const VkAllocationCallbacks* a) {
    vkDestroyBufferView(d, h, a);
}

using BufferHandle = DeviceHandle<VkBuffer, destroyBuffer>;
using MemoryHandle = DeviceHandle<VkDeviceMemory, freeMemory>;
using ShaderModuleHandle = DeviceHandle<VkShaderModule, destroyShaderModule>;
using DescriptorSetLayoutHandle = DeviceHandle<VkDescriptorSetLayout, destroyDescriptorSetLayout>;
using DescriptorPoolHandle = DeviceHandle<VkDescriptorPool, destroyDescriptorPool>;
using PipelineLayoutHandle = DeviceHandle<VkPipelineLayout, destroyPipelineLayout>;
using PipelineHandle = DeviceHandle<VkPipeline, destroyPipeline>;
using CommandPoolHandle = DeviceHandle<VkCommandPool, destroyCommandPool>;
using FenceHandle = DeviceHandle<VkFence, destroyFence>;
using BufferViewHandle = DeviceHandle<VkBufferView, destroyBufferView>;

} // namespace wavelit::vk
