// Limits said up front (issue 15): before the Vulkan tracer allocates anything, every buffer it
// will need is sized (GpuMemoryPlan) and checked against the device's limits: each storage buffer
// against VkPhysicalDeviceLimits::maxStorageBufferRange (128 MiB on lavapipe), the render width and
// height against maxComputeWorkGroupCount, and the sum against the memory heap the buffers come
// from. A request that does not fit is refused with one message naming what is too big (the
// render size, the meshes, the environment map, the sampling tables), by how much, and what to do,
// instead of a failed allocation half-way or a device loss. The CPU tracer's image memory is
// checked against the machine's memory the same way. Pure functions, no device work, except
// gpuDeviceLimits, which only reads the context's properties.
#pragma once

#include "util/result.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace wavelit::vk {
class Context;
}

namespace wavelit::render {

// One buffer of the plan.
struct GpuBufferPlan {
    std::string name;   // the buffer's debug name: "accumulation", "bvh triangles", ...
    uint64_t bytes = 0;
    uint64_t count = 0; // elements it holds (pixels, triangles, texels...); 0: not counted
    std::string unit;   // what count counts: "pixels", "triangles", "texels", ...
    std::string what;   // what the user chose that sets its size: "the render size 640x480"
    std::string remedy; // what makes it smaller: "render at a smaller size"
};

struct GpuDeviceLimits {
    std::string deviceName;
    uint64_t maxStorageBufferRange = 0;       // 0: unchecked
    uint64_t memoryHeapBytes = 0;             // the host-visible heap; 0: unchecked
    uint32_t maxWorkGroupCount[2] = {0, 0};   // x, y; 0: unchecked
};

struct GpuMemoryPlan {
    int width = 0, height = 0; // the render size (workgroup check, size suggestion)
    uint32_t workgroupWidth = 8, workgroupHeight = 8;
    std::vector<GpuBufferPlan> buffers;
    uint64_t totalBytes() const;
};

// The float RGBA sum per pixel that each pass adds to (16 bytes a pixel).
GpuBufferPlan gpuAccumulationPlan(int width, int height);

// OK when everything fits; otherwise an ErrorKind::Invalid error (no file) for the first problem:
// the render size's workgroups, then each buffer against the storage-buffer range, then the total
// against the heap.
util::Status checkGpuMemoryPlan(const GpuMemoryPlan& plan, const GpuDeviceLimits& limits);

// The limits of the context's device (the heap is the one Buffer::create allocates from).
GpuDeviceLimits gpuDeviceLimits(const vk::Context& context);

// The CPU tracer keeps a double RGB sum and a float RGB image per pixel (36 bytes), and with
// light groups a double RGB sum per group and pixel (24 bytes each); a size whose buffers exceed
// half of physicalBytes is refused (ErrorKind::Invalid). physicalBytes 0: unchecked.
util::Status checkCpuImageMemory(int width, int height, uint64_t physicalBytes,
                                 size_t lightGroups = 0);

// The LightMix layers of the Vulkan tracer (float RGB per group and pixel, 12 bytes each:
// light_groups.h), as one storage buffer.
GpuBufferPlan gpuLightGroupPlan(size_t groups, int width, int height);
// The machine's physical memory in bytes; 0 when unknown.
uint64_t physicalMemoryBytes();

// A pass's error: a lost device (VK_ERROR_DEVICE_LOST from a submit or a wait) is said so, naming
// the device, ahead of the Vulkan call that reported it; any other error is returned as it is.
util::Error describePassError(util::Error error, const std::string& deviceName);

} // namespace wavelit::render
