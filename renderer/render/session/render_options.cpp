#include "render/session/render_options.h"

#include <array>
#include <utility>

namespace wavelit::render {
namespace {
constexpr std::array<std::pair<SamplerKind, const char*>, 7> kSamplerNames{{
    {SamplerKind::Uniform, "uniform"},
    {SamplerKind::Cosine, "cosine"},
    {SamplerKind::Bsdf, "bsdf"},
    {SamplerKind::Env, "env"},
    {SamplerKind::Mis, "mis"},
    {SamplerKind::Wavelet, "wavelet"},
    {SamplerKind::Oracle, "oracle"},
}};
constexpr std::array<std::pair<DeviceChoice, const char*>, 3> kDeviceNames{{
    {DeviceChoice::Auto, "auto"},
    {DeviceChoice::Vulkan, "vulkan"},
    {DeviceChoice::Cpu, "cpu"},
}};
} // namespace

util::Result<DeviceChoice> parseDeviceChoice(const std::string& text) {
    for (auto [kind, name] : kDeviceNames)
        if (text == name) return kind;
    return util::makeError(util::ErrorKind::Usage, "",
                           "--device must be auto, cpu or vulkan, got '" + text + "'");
}

util::Result<SamplerKind> parseSamplerKind(const std::string& text) {
    for (auto [kind, name] : kSamplerNames)
        if (text == name) return kind;
    return util::makeError(util::ErrorKind::Usage, "",
                           "--sampler must be one of uniform, cosine, bsdf, env, mis, wavelet, "
                           "oracle; got '" + text + "'");
}

const char* samplerKindName(SamplerKind kind) {
    for (auto [k, name] : kSamplerNames)
        if (k == kind) return name;
    return "?";
}

const char* deviceChoiceName(DeviceChoice kind) {
    for (auto [k, name] : kDeviceNames)
        if (k == kind) return name;
    return "?";
}

} // namespace wavelit::render
