#include "vk/buffer.h"

#include "util/check.h"
#include "vk/context.h"
#include "vk/vk_error.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace wavelit::vk {

util::Result<Buffer> Buffer::create(const Context& ctx, size_t size, VkBufferUsageFlags usage,
                                    const std::string& debugName) {
    constexpr size_t kMinimumSize = 16;
    size = std::max(size, kMinimumSize);
    Buffer b;
    b.m_device = ctx.device();
    b.m_size = size;
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    WAVELIT_VK_TRY(vkCreateBuffer(ctx.device(), &info, nullptr, &buffer),
                   "vkCreateBuffer(" + debugName + ")");
    b.m_buffer = BufferHandle(ctx.device(), buffer);
    ctx.setName(VK_OBJECT_TYPE_BUFFER, uint64_t(buffer), debugName);

    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(ctx.device(), buffer, &req);
    uint32_t type =
        ctx.findMemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                   VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    if (type == UINT32_MAX)
        return util::makeError(util::ErrorKind::Device, "",
                               debugName + ": no host-visible coherent memory type");
    VkMemoryAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = type;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    WAVELIT_VK_TRY(vkAllocateMemory(ctx.device(), &alloc, nullptr, &memory),
                   "vkAllocateMemory(" + debugName + ", " + std::to_string(req.size) + " bytes)");
    b.m_memory = MemoryHandle(ctx.device(), memory);
    ctx.setName(VK_OBJECT_TYPE_DEVICE_MEMORY, uint64_t(memory), debugName + " memory");
    WAVELIT_VK_TRY(vkBindBufferMemory(ctx.device(), buffer, memory, 0),
                   "vkBindBufferMemory(" + debugName + ")");
    WAVELIT_VK_TRY(vkMapMemory(ctx.device(), memory, 0, VK_WHOLE_SIZE, 0, &b.m_mapped),
                   "vkMapMemory(" + debugName + ")");
    return b;
}

Buffer::~Buffer() {
    unmap();
}

Buffer::Buffer(Buffer&& o) noexcept
    : m_memory(std::move(o.m_memory)), m_buffer(std::move(o.m_buffer)), m_device(o.m_device),
      m_size(o.m_size), m_mapped(std::exchange(o.m_mapped, nullptr)) {}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
    if (this != &o) {
        unmap();
        m_buffer = std::move(o.m_buffer);
        m_memory = std::move(o.m_memory);
        m_device = o.m_device;
        m_size = o.m_size;
        m_mapped = std::exchange(o.m_mapped, nullptr);
    }
    return *this;
}

void Buffer::unmap() {
    if (m_mapped && m_memory)
        vkUnmapMemory(m_device, m_memory.get());
    m_mapped = nullptr;
}

void Buffer::write(const void* data, size_t bytes, size_t offset) {
    WAVELIT_CHECK(m_mapped && offset + bytes <= m_size);
    std::memcpy(static_cast<char*>(m_mapped) + offset, data, bytes);
}

void Buffer::read(void* data, size_t bytes, size_t offset) const {
    WAVELIT_CHECK(m_mapped && offset + bytes <= m_size);
    std::memcpy(data, static_cast<const char*>(m_mapped) + offset, bytes);
}

void Buffer::fill(unsigned char value) {
    WAVELIT_CHECK(m_mapped);
    std::memset(m_mapped, value, m_size);
}

} // namespace wavelit::vk
