#include "render/gpu/render_limits.h"

#include "vk/context.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <unistd.h>

namespace wavelit::render {
namespace {

std::string formatBytes(uint64_t bytes) {
    char text[64];
    if (bytes >= (uint64_t(1) << 20))
        std::snprintf(text, sizeof(text), "%.1f MiB", double(bytes) / double(1 << 20));
    else if (bytes >= 1024)
        std::snprintf(text, sizeof(text), "%.1f KiB", double(bytes) / 1024.0);
    else
        std::snprintf(text, sizeof(text), "%llu bytes", static_cast<unsigned long long>(bytes));
    return text;
}

std::string sizeText(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

// The largest size with the aspect ratio of width x height that has at most maxPixels pixels.
std::string suggestedSize(int width, int height, uint64_t maxPixels) {
    const double scale = std::sqrt(double(maxPixels) / (double(width) * double(height)));
    int64_t w = std::max<int64_t>(1, int64_t(std::floor(double(width) * scale)));
    int64_t h = std::max<int64_t>(1, int64_t(std::floor(double(height) * scale)));
    while (uint64_t(w) * uint64_t(h) > maxPixels && (w > 1 || h > 1)) {
        if (w >= h) --w; else --h;
    }
    return std::to_string(w) + "x" + std::to_string(h);
}

util::Error limitError(std::string reason) {
    return util::makeError(util::ErrorKind::Invalid, "", std::move(reason));
}

} // namespace

uint64_t GpuMemoryPlan::totalBytes() const {
    uint64_t total = 0;
    for (const auto& b : buffers)
        total += b.bytes;
    return total;
}

GpuBufferPlan gpuAccumulationPlan(int width, int height) {
    const uint64_t pixels = uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0));
    return {"accumulation", pixels * 4 * sizeof(float), pixels, "pixels",
            "the render size " + sizeText(width, height), "render at a smaller size"};
}

GpuBufferPlan gpuLightGroupPlan(size_t groups, int width, int height) {
    const uint64_t pixels = uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0));
    return {"light groups", uint64_t(groups) * pixels * 3 * sizeof(float), uint64_t(groups) * pixels,
            "group pixels",
            "--light-groups (" + std::to_string(groups) + " layers of " + sizeText(width, height) +
                ", 12 bytes a pixel each)",
            "merge lights into fewer groups (the light's `group` property), render without "
            "--light-groups, or render at a smaller size"};
}

util::Status checkGpuMemoryPlan(const GpuMemoryPlan& plan, const GpuDeviceLimits& limits) {
    const std::string device = limits.deviceName.empty() ? "the Vulkan device" : limits.deviceName;
    // Workgroups: a pass dispatches ceil(W / 8) x ceil(H / 8) of them.
    const uint64_t groups[2] = {
        (uint64_t(std::max(plan.width, 0)) + plan.workgroupWidth - 1) / plan.workgroupWidth,
        (uint64_t(std::max(plan.height, 0)) + plan.workgroupHeight - 1) / plan.workgroupHeight};
    const uint32_t groupPixels[2] = {plan.workgroupWidth, plan.workgroupHeight};
    const char* side[2] = {"width", "height"};
    for (int axis = 0; axis < 2; ++axis)
        if (limits.maxWorkGroupCount[axis] > 0 && groups[axis] > limits.maxWorkGroupCount[axis])
            return limitError(
                "the render size " + sizeText(plan.width, plan.height) + " is too big for " +
                device + ": its " + side[axis] + " needs " + std::to_string(groups[axis]) +
                " workgroups of " + std::to_string(groupPixels[axis]) + " pixels, more than the " +
                "device's limit of " + std::to_string(limits.maxWorkGroupCount[axis]) +
                " (maxComputeWorkGroupCount); render at most " +
                std::to_string(uint64_t(limits.maxWorkGroupCount[axis]) * groupPixels[axis]) +
                " pixels in " + side[axis]);

    // Every buffer is a storage buffer bound whole: each must fit maxStorageBufferRange.
    const uint64_t range = limits.maxStorageBufferRange;
    for (const auto& b : plan.buffers) {
        if (range == 0 || b.bytes <= range)
            continue;
        std::string reason = b.what + " is too big for " + device + ": its " + b.name +
                             " buffer needs " + formatBytes(b.bytes);
        if (b.count > 0)
            reason += " (" + std::to_string(b.count) + " " + b.unit + ")";
        reason += ", " + formatBytes(b.bytes - range) + " more than the device's storage-buffer " +
                  "limit of " + formatBytes(range) + " (maxStorageBufferRange)";
        if (!b.remedy.empty())
            reason += "; " + b.remedy;
        if (b.count > 0) {
            const uint64_t maxCount = range / std::max<uint64_t>(1, b.bytes / b.count);
            reason += ": at most " + std::to_string(maxCount) + " " + b.unit + " fit";
            if (b.unit == "pixels" && plan.width > 0 && plan.height > 0)
                reason += ", e.g. " + suggestedSize(plan.width, plan.height, maxCount);
        }
        return limitError(std::move(reason));
    }

    // All of them together come from one heap.
    const uint64_t total = plan.totalBytes();
    if (limits.memoryHeapBytes > 0 && total > limits.memoryHeapBytes) {
        std::vector<const GpuBufferPlan*> largest;
        for (const auto& b : plan.buffers)
            largest.push_back(&b);
        std::sort(largest.begin(), largest.end(),
                  [](const GpuBufferPlan* a, const GpuBufferPlan* b) { return a->bytes > b->bytes; });
        largest.resize(std::min<size_t>(largest.size(), 3));
        std::string parts;
        for (const GpuBufferPlan* b : largest)
            parts += (parts.empty() ? "" : ", ") + b->name + " " + formatBytes(b->bytes);
        std::string remedies;
        for (const GpuBufferPlan* b : largest)
            if (!b->remedy.empty() && remedies.find(b->remedy) == std::string::npos)
                remedies += (remedies.empty() ? "" : ", or ") + b->remedy;
        return limitError("the render needs " + formatBytes(total) + " of device memory in all, " +
                          formatBytes(total - limits.memoryHeapBytes) + " more than " + device +
                          "'s memory heap of " + formatBytes(limits.memoryHeapBytes) +
                          " (largest buffers: " + parts + ")" +
                          (remedies.empty() ? "" : "; " + remedies));
    }
    return util::okStatus();
}

GpuDeviceLimits gpuDeviceLimits(const vk::Context& context) {
    GpuDeviceLimits limits;
    limits.deviceName = context.deviceName();
    const VkPhysicalDeviceLimits& l = context.limits();
    limits.maxStorageBufferRange = l.maxStorageBufferRange;
    limits.maxWorkGroupCount[0] = l.maxComputeWorkGroupCount[0];
    limits.maxWorkGroupCount[1] = l.maxComputeWorkGroupCount[1];
    // The heap of the memory type Buffer::create picks (the first host-visible coherent one).
    VkPhysicalDeviceMemoryProperties memory{};
    vkGetPhysicalDeviceMemoryProperties(context.physicalDevice(), &memory);
    const uint32_t type = context.findMemoryType(
        ~0u, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    if (type < memory.memoryTypeCount)
        limits.memoryHeapBytes = memory.memoryHeaps[memory.memoryTypes[type].heapIndex].size;
    return limits;
}

util::Status checkCpuImageMemory(int width, int height, uint64_t physicalBytes,
                                 size_t lightGroups) {
    const uint64_t bytesPerPixel =
        3 * sizeof(double) + 3 * sizeof(float) + uint64_t(lightGroups) * 3 * sizeof(double);
    const uint64_t pixels = uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0));
    const uint64_t bytes = pixels * bytesPerPixel;
    const uint64_t budget = physicalBytes / 2;
    if (physicalBytes == 0 || bytes <= budget)
        return util::okStatus();
    const uint64_t maxPixels = budget / bytesPerPixel;
    return limitError("the render size " + sizeText(width, height) +
                      " is too big for the CPU tracer: its image buffers need " + formatBytes(bytes) +
                      (lightGroups ? " with " + std::to_string(lightGroups) + " light groups" : "") +
                      " (" + std::to_string(bytesPerPixel) + " bytes a pixel), " +
                      formatBytes(bytes - budget) + " more than half of this machine's " +
                      formatBytes(physicalBytes) + " of memory; render at a smaller size: at most " +
                      std::to_string(maxPixels) + " pixels fit, e.g. " +
                      suggestedSize(width, height, maxPixels));
}

uint64_t physicalMemoryBytes() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageSize = sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || pageSize <= 0)
        return 0;
    return uint64_t(pages) * uint64_t(pageSize);
}

util::Error describePassError(util::Error error, const std::string& deviceName) {
    if (error.reason.find("VK_ERROR_DEVICE_LOST") == std::string::npos)
        return error;
    error.kind = util::ErrorKind::Device;
    error.reason = "the Vulkan device was lost (VK_ERROR_DEVICE_LOST) while rendering on " +
                   (deviceName.empty() ? std::string("the Vulkan device") : deviceName) + ": " +
                   error.reason + "; the render stopped, and a new render starts on a fresh device";
    return error;
}

} // namespace wavelit::render
