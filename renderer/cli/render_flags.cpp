#include "cli/render_flags.h"

namespace wavelit::cli {

namespace {
constexpr int kMaxImageSide = 16384; // a side beyond this would not fit a storage buffer anyway
constexpr int kMaxBounces = 1024;
} // namespace

const std::set<std::string>& renderValueFlags() {
    static const std::set<std::string> flags{"--width", "--height", "--seed", "--bounces",
                                             "--device", "--sampler"};
    return flags;
}

util::Result<render::RenderOptions> renderOptionsFromArgs(const Args& args,
                                                          const scene::RenderDefaults& defaults) {
    render::RenderOptions o;
    // The CLI's default sampler is the wavelet product sampler (architecture.md §5.B); the library's
    // RenderOptions default stays `bsdf`, the cheapest, for code that does not choose.
    o.sampler = render::SamplerKind::Wavelet;
    auto width = args.intValue("--width", defaults.width, 1, kMaxImageSide);
    if (!width) return width.error();
    auto height = args.intValue("--height", defaults.height, 1, kMaxImageSide);
    if (!height) return height.error();
    auto bounces = args.intValue("--bounces", defaults.bounces, 0, kMaxBounces);
    if (!bounces) return bounces.error();
    auto seed = args.uint64Value("--seed", o.seed);
    if (!seed) return seed.error();
    o.width = *width;
    o.height = *height;
    o.bounces = *bounces;
    o.seed = *seed;
    if (auto d = args.value("--device")) {
        auto device = render::parseDeviceChoice(*d);
        if (!device) return device.error();
        o.device = *device;
    }
    if (auto s = args.value("--sampler")) {
        auto sampler = render::parseSamplerKind(*s);
        if (!sampler) return sampler.error();
        o.sampler = *sampler;
    }
    return o;
}

} // namespace wavelit::cli
