#include "vk/context.h"

#include "util/log.h"
#include "vk/vk_error.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>

namespace wavelit::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

bool envFlag(const char* name) {
    const char* v = std::getenv(name);
    return v && std::strcmp(v, "1") == 0;
}

bool hasLayer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const auto& l : layers)
        if (std::strcmp(l.layerName, name) == 0)
            return true;
    return false;
}

// Preference when no device is named: hardware first, the CPU rasteriser last.
int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return 3;
    default:
        return 4;
    }
}

// `messenger`, when given, also reports messages from vkCreateInstance/vkDestroyInstance.
util::Result<VkInstance>
createInstance(bool validation, const VkDebugUtilsMessengerCreateInfoEXT* messenger = nullptr) {
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "wavelit";
    app.apiVersion = VK_API_VERSION_1_2;
    std::vector<const char*> layers, extensions;
    if (validation) {
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pNext = messenger;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkInstance instance = VK_NULL_HANDLE;
    WAVELIT_VK_TRY(vkCreateInstance(&info, nullptr, &instance), "vkCreateInstance");
    return instance;
}

} // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL Context::debugCallback(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* self = static_cast<Context*>(user);
    if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        self->m_validationMessages.fetch_add(1);
        util::logError(std::string("vulkan validation: ") + (data ? data->pMessage : "?"));
    }
    return VK_FALSE;
}

util::Result<std::vector<PhysicalDeviceInfo>> Context::listDevices() {
    auto instance = createInstance(false);
    if (!instance)
        return instance.error();
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(*instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(*instance, &count, devices.data());
    std::vector<PhysicalDeviceInfo> out;
    for (uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(devices[i], &p);
        out.push_back({i, p.deviceName, p.deviceType});
    }
    vkDestroyInstance(*instance, nullptr);
    return out;
}

util::Result<std::unique_ptr<Context>> Context::create(const ContextOptions& options) {
    std::unique_ptr<Context> ctx(new Context());
    bool validation = options.validation || envFlag("WAVELIT_VK_VALIDATION");
    if (validation && !hasLayer(kValidationLayer)) {
        util::logWarning("vulkan: VK_LAYER_KHRONOS_validation not installed; validation off");
        validation = false;
    }
    VkDebugUtilsMessengerCreateInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = &Context::debugCallback;
    info.pUserData = ctx.get();
    auto instance = createInstance(validation, validation ? &info : nullptr);
    if (!instance)
        return instance.error();
    ctx->m_instance = *instance;

    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(ctx->m_instance, "vkCreateDebugUtilsMessengerEXT"));
        if (!create)
            return util::makeError(util::ErrorKind::Device, "",
                                   "vkCreateDebugUtilsMessengerEXT not available");
        WAVELIT_VK_TRY(create(ctx->m_instance, &info, nullptr, &ctx->m_messenger),
                       "vkCreateDebugUtilsMessengerEXT");
    }

    uint32_t count = 0;
    WAVELIT_VK_TRY(vkEnumeratePhysicalDevices(ctx->m_instance, &count, nullptr),
                   "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    WAVELIT_VK_TRY(vkEnumeratePhysicalDevices(ctx->m_instance, &count, devices.data()),
                   "vkEnumeratePhysicalDevices");
    if (devices.empty())
        return util::makeError(util::ErrorKind::Unsupported, "", "no Vulkan device found");

    std::string selector = options.device;
    if (selector.empty())
        if (const char* env = std::getenv("WAVELIT_VK_DEVICE"))
            selector = env;
    std::string available;
    int chosen = -1;
    for (uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(devices[i], &p);
        available += (available.empty() ? "" : ", ") + std::to_string(i) + ": " + p.deviceName;
        if (selector.empty()) {
            if (chosen < 0) {
                chosen = int(i);
            } else {
                VkPhysicalDeviceProperties best;
                vkGetPhysicalDeviceProperties(devices[chosen], &best);
                if (typeRank(p.deviceType) < typeRank(best.deviceType))
                    chosen = int(i);
            }
        } else if (std::all_of(selector.begin(), selector.end(), ::isdigit)) {
            if (std::stoul(selector) == i)
                chosen = int(i);
        } else if (chosen < 0 && lower(p.deviceName).find(lower(selector)) != std::string::npos) {
            chosen = int(i);
        }
    }
    if (chosen < 0)
        return util::makeError(util::ErrorKind::NotFound, "",
                               "no Vulkan device matches '" + selector +
                                   "' (available: " + available + ")");
    ctx->m_physical = devices[chosen];
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(ctx->m_physical, &props);
    ctx->m_deviceName = props.deviceName;
    ctx->m_cpuDevice = props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    ctx->m_limits = props.limits;
    vkGetPhysicalDeviceMemoryProperties(ctx->m_physical, &ctx->m_memory);

    VkPhysicalDeviceFeatures features;
    vkGetPhysicalDeviceFeatures(ctx->m_physical, &features);
    if (!features.shaderInt64)
        return util::makeError(util::ErrorKind::Unsupported, "",
                               ctx->m_deviceName + ": shaderInt64 is required (PCG32 state)");

    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx->m_physical, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx->m_physical, &familyCount, families.data());
    int family = -1;
    for (uint32_t i = 0; i < familyCount && family < 0; ++i)
        if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT)
            family = int(i);
    if (family < 0)
        return util::makeError(util::ErrorKind::Unsupported, "",
                               ctx->m_deviceName + ": no compute queue");
    ctx->m_queueFamily = uint32_t(family);

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{};
    queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queueInfo.queueFamilyIndex = ctx->m_queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkPhysicalDeviceFeatures enabled{};
    enabled.shaderInt64 = VK_TRUE;
    // Doubles carry the sampling descents' random numbers (shaders/sampling/).
    enabled.shaderFloat64 = features.shaderFloat64;
    ctx->m_float64 = features.shaderFloat64 == VK_TRUE;
    VkDeviceCreateInfo deviceInfo{};
    deviceInfo.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.pEnabledFeatures = &enabled;
    WAVELIT_VK_TRY(vkCreateDevice(ctx->m_physical, &deviceInfo, nullptr, &ctx->m_device),
                   "vkCreateDevice(" + ctx->m_deviceName + ")");
    vkGetDeviceQueue(ctx->m_device, ctx->m_queueFamily, 0, &ctx->m_queue);
    if (validation)
        ctx->m_setObjectName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
            vkGetDeviceProcAddr(ctx->m_device, "vkSetDebugUtilsObjectNameEXT"));
    return ctx;
}

Context::~Context() {
    if (m_device) {
        vkDeviceWaitIdle(m_device);
        vkDestroyDevice(m_device, nullptr);
    }
    if (m_messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(m_instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy)
            destroy(m_instance, m_messenger, nullptr);
    }
    if (m_instance)
        vkDestroyInstance(m_instance, nullptr);
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const {
    for (uint32_t i = 0; i < m_memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) &&
            (m_memory.memoryTypes[i].propertyFlags & required) == required)
            return i;
    return UINT32_MAX;
}

void Context::setName(VkObjectType type, uint64_t handle, const std::string& name) const {
    if (!m_setObjectName)
        return;
    VkDebugUtilsObjectNameInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT;
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name.c_str();
    m_setObjectName(m_device, &info);
}

} // namespace wavelit::vk
