// A storage/uniform buffer in host-visible, host-coherent memory, persistently mapped. On lavapipe
// all memory is host memory, so staging copies would only cost time; on a discrete GPU this reads
// scene data over PCIe, which is acceptable for the walking skeleton (a device-local path with a
// staging copy can be added behind the same interface when a hardware GPU matters).
#pragma once

#include "util/result.h"
#include "vk/handle.h"

#include <cstddef>
#include <string>

namespace wavelit::vk {

class Context;

class Buffer {
public:
    Buffer() = default;
    // size 0 is rounded up to 16 bytes so empty arrays still bind (Vulkan forbids empty buffers).
    static util::Result<Buffer> create(const Context& ctx, size_t size, VkBufferUsageFlags usage,
                                       const std::string& debugName);
    ~Buffer();
    Buffer(Buffer&&) noexcept;
    Buffer& operator=(Buffer&&) noexcept;

    VkBuffer handle() const { return m_buffer.get(); }
    size_t size() const { return m_size; }
    void* mapped() const { return m_mapped; }
    // Copies bytes in at offset; the caller keeps offset + bytes <= size().
    void write(const void* data, size_t bytes, size_t offset = 0);
    void read(void* data, size_t bytes, size_t offset = 0) const;
    void fill(unsigned char value);

private:
    void unmap();
    // Buffer before memory so the buffer is destroyed first.
    MemoryHandle m_memory;
    BufferHandle m_buffer;
    VkDevice m_device = VK_NULL_HANDLE;
    size_t m_size = 0;
    void* m_mapped = nullptr;
};

} // namespace wavelit::vk
