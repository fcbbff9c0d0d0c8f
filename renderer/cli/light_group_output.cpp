#include "cli/light_group_output.h"

#include "scene/exr_layers.h"
#include "util/path_util.h"

#include <cstdio>

namespace wavelit::cli {

util::Status checkLightGroupFlags(const Args& args, const std::string& output) {
    using util::ErrorKind;
    if (!args.has("--light-groups")) return util::okStatus();
    if (util::lowerExtension(output) != ".exr")
        return util::makeError(ErrorKind::Usage, output,
                               "--light-groups writes layers: -o must be an .exr");
    for (const char* flag : {"--passes", "--mpi"})
        if (args.has(flag))
            return util::makeError(ErrorKind::Usage, "",
                                   std::string("--light-groups does not combine with ") + flag +
                                       " (parts are merged as beauty only)");
    return util::okStatus();
}

std::string describeLightGroups(const render::LightGroups& groups, int width, int height) {
    std::string names;
    for (const std::string& n : groups.names) names += (names.empty() ? "" : ", ") + n;
    const double mib =
        double(render::lightGroupLayerBytes(groups.size(), width, height)) / double(1 << 20);
    char text[160];
    std::snprintf(text, sizeof text, "%zu layers of 12 bytes a pixel: %.1f MiB at %dx%d",
                  groups.size(), mib, width, height);
    return "light groups: " + std::string(text) + " (" + names +
           "; the CPU reference sums in double, twice that)";
}

util::Status writeLightGroupExr(const std::string& path, render::RenderSession& session,
                                const util::ImageRGB& beauty,
                                const scene::ExrAttributes& attributes) {
    auto layers = session.groupImages();
    if (!layers) return layers.error();
    const render::LightGroups groups = session.lightGroups();
    scene::LayeredImage out;
    out.beauty = beauty;
    out.attributes = attributes;
    for (size_t g = 0; g < groups.size() && g < layers->size(); ++g)
        out.layers.push_back({groups.names[g], std::move((*layers)[g])});
    return scene::writeExrLayers(path, out);
}

} // namespace wavelit::cli
