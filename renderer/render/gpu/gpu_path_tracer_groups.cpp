// GpuPathTracer's LightMix layers (docs/lightmix.md): the group info buffer and the float RGB
// layers path_tracer.comp adds to with WAVELIT_LIGHT_GROUPS (shaders/common/light_groups.glsl),
// sized from the scene's light groups and checked against the device's limits before anything
// is allocated (uploadScene adds gpuLightGroupPlan to its plan).
#include "render/gpu/gpu_path_tracer_impl.h"

#include <algorithm>

namespace wavelit::render::gpu_tracer {

std::vector<uint32_t> packGpuLightGroups(const LightGroups& groups, uint64_t pixels) {
    auto code = [](int group) { return group < 0 ? kNoLightGroup : uint32_t(group); };
    std::vector<uint32_t> words = {uint32_t(groups.size()), code(groups.environmentGroup),
                                   code(groups.emissionGroup), uint32_t(pixels)};
    for (int g : groups.groupOfLight) words.push_back(code(g));
    return words;
}

util::Status GpuPathTracer::uploadLightGroups(const scene::Scene& scene) {
    const LightGroups groups = lightGroupsOf(scene);
    const uint64_t pixels = uint64_t(m_options.width) * uint64_t(m_options.height);
    const std::vector<uint32_t> info = packGpuLightGroups(groups, pixels);
    const size_t infoBytes = info.size() * sizeof(uint32_t);
    const uint64_t layerBytes = gpuLightGroupPlan(groups.size(), m_options.width, m_options.height).bytes;
    // Created before anything is written, so a failure leaves the previous layers intact.
    vk::Buffer newInfo, newLayers;
    constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    if (m_groupInfo.handle() == VK_NULL_HANDLE || m_groupInfo.size() != std::max<size_t>(infoBytes, 16)) {
        auto b = upload(nullptr, infoBytes, kStorage, "light group info");
        if (!b) return b.error();
        newInfo = std::move(b.value());
    }
    if (m_groupLayers.handle() == VK_NULL_HANDLE || m_groupLayers.size() != layerBytes) {
        auto b = upload(nullptr, layerBytes, kStorage, "light groups");
        if (!b) return b.error();
        newLayers = std::move(b.value());
    }
    if (newInfo.handle() != VK_NULL_HANDLE) {
        m_groupInfo = std::move(newInfo);
        bindAll(m_groupBinding, m_groupInfo);
    }
    if (newLayers.handle() != VK_NULL_HANDLE) {
        m_groupLayers = std::move(newLayers);
        bindAll(m_groupBinding + 1, m_groupLayers);
        m_groupLayers.fill(0);
    }
    m_groupInfo.write(info.data(), infoBytes);
    m_groupCount = groups.size();
    return util::okStatus();
}

util::Result<std::vector<util::ImageRGB>> GpuPathTracer::groupImages() {
    std::vector<util::ImageRGB> layers;
    if (!m_options.lightGroups) return layers;
    const size_t pixels = size_t(m_options.width) * size_t(m_options.height);
    std::vector<float> sums(m_groupCount * pixels * 3);
    if (m_passes > 0) m_groupLayers.read(sums.data(), sums.size() * sizeof(float));
    const float inv = m_passes > 0 ? 1.0f / float(m_passes) : 0.0f;
    for (size_t g = 0; g < m_groupCount; ++g) {
        util::ImageRGB img(m_options.width, m_options.height);
        const float* layer = sums.data() + g * pixels * 3;
        for (size_t p = 0; p < pixels; ++p)
            img.pixels[p] = glm::vec3(layer[3 * p], layer[3 * p + 1], layer[3 * p + 2]) * inv;
        layers.push_back(std::move(img));
    }
    return layers;
}

} // namespace wavelit::render::gpu_tracer
