// `wavelit-cli render SCENE -o OUT.exr|png [--spp N] [--time SECONDS] [--sampler NAME]
//  [--width W --height H] [--seed S] [--bounces B] [--device auto|cpu|vulkan] [--report R.json]`
// (DESIGN.md §6). Size and bounces default to the scene's render settings. Passes run until --spp
// is reached or --time has elapsed (both: whichever comes first; neither: kDefaultSpp). PNG output
// applies the camera's exposure (display transform); EXR stores linear radiance. Exit codes:
// 0 success, 1 bad input (message names the file), 2 bad usage.
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/render_flags.h"
#include "render/render_session.h"
#include "scene/atomic_file.h"
#include "scene/image_io.h"
#include "scene/scene_io.h"
#include "util/path_util.h"
#include "util/log.h"
#include "util/timer.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

namespace wavelit::cli {
namespace {

using util::ErrorKind;
using util::makeError;

constexpr int kDefaultSpp = 16;
constexpr int kMaxSpp = 1 << 20;

std::string jsonEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else {
            out += c;
        }
    }
    return out;
}

std::string reportJson(const std::string& scenePath, const std::string& output,
                       const render::RenderOptions& o, const render::RenderStats& s,
                       size_t lightCount, double totalSeconds) {
    std::ostringstream j;
    j.precision(9);
    double perPass = s.samplesPerPixel > 0 ? s.timings.passSeconds / s.samplesPerPixel : 0.0;
    j << "{\n"
      << "  \"scene\": \"" << jsonEscape(scenePath) << "\",\n"
      << "  \"output\": \"" << jsonEscape(output) << "\",\n"
      << "  \"device\": \"" << jsonEscape(s.deviceName) << "\",\n"
      << "  \"deviceChoice\": \"" << render::deviceChoiceName(o.device) << "\",\n"
      << "  \"sampler\": \"" << render::samplerKindName(o.sampler) << "\",\n"
      << "  \"width\": " << o.width << ",\n"
      << "  \"height\": " << o.height << ",\n"
      << "  \"bounces\": " << o.bounces << ",\n"
      << "  \"seed\": " << o.seed << ",\n"
      << "  \"spp\": " << s.samplesPerPixel << ",\n"
      << "  \"validationMessages\": " << s.validationMessages << ",\n"
      << "  \"timings\": {\n"
      << "    \"bvhBuildSeconds\": " << s.timings.bvhBuildSeconds << ",\n"
      << "    \"uploadSeconds\": " << s.timings.uploadSeconds << ",\n"
      << "    \"pipelineSeconds\": " << s.timings.pipelineSeconds << ",\n"
      << "    \"passSeconds\": " << s.timings.passSeconds << ",\n"
      << "    \"secondsPerPass\": " << perPass << ",\n"
      << "    \"totalSeconds\": " << totalSeconds << "\n"
      << "  },\n"
      << "  \"choices\": [\n"
      << "    {\"what\": \"sampler\", \"value\": \"" << render::samplerKindName(o.sampler)
      << "\", \"reason\": \"chosen with --sampler (default bsdf until issue 6)\"}";
    // Both tracers render analytic lights the same way (docs/estimator.md "Analytic lights").
    if (lightCount > 0)
        j << ",\n    {\"what\": \"analytic lights\", \"value\": \"nee+mis\", "
             "\"reason\": \""
          << lightCount
          << " light(s): next-event estimation, uniform selection, power-heuristic MIS with "
             "BSDF sampling\"}";
    j << "\n"
      << "  ]\n"
      << "}\n";
    return j.str();
}

using util::lowerExtension;

int run(const std::vector<std::string>& argv) {
    std::set<std::string> flags = renderValueFlags();
    flags.insert({"-o", "--spp", "--time", "--report"});
    auto args = Args::parse(argv, flags);
    if (!args)
        return reportError(args.error());
    if (args->positional().size() != 1)
        return reportError(makeError(ErrorKind::Usage, "", "render needs exactly one SCENE file"));
    auto output = args->value("-o");
    if (!output)
        return reportError(makeError(ErrorKind::Usage, "", "render needs -o OUT.exr|png"));
    std::string ext = lowerExtension(*output);
    if (ext != ".exr" && ext != ".png")
        return reportError(makeError(ErrorKind::Usage, *output, "output must end in .exr or .png"));
    auto spp = args->intValue("--spp", kDefaultSpp, 1, kMaxSpp);
    auto seconds = args->doubleValue("--time", 0.0, 0.0, 1e7);
    if (!spp)
        return reportError(spp.error());
    if (!seconds)
        return reportError(seconds.error());
    // Usage errors in the shared render flags surface before the scene is loaded.
    if (auto early = renderOptionsFromArgs(*args, scene::RenderDefaults{}); !early)
        return reportError(early.error());

    const std::string scenePath = args->positional()[0];
    scene::LoadReport loadReport;
    auto scene = scene::loadScene(scenePath, &loadReport);
    for (const auto& w : loadReport.warnings)
        std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (!scene) {
        util::Error e = scene.error();
        if (e.file.empty())
            e.file = scenePath;
        return reportError(e);
    }
    auto parsed = renderOptionsFromArgs(*args, scene->render);
    if (!parsed)
        return reportError(parsed.error());
    render::RenderOptions options = *parsed;

    util::Timer total;
    auto session = render::RenderSession::create(*scene, options);
    if (!session)
        return reportError(session.error());
    const bool timed = args->has("--time");
    const int maxSpp = timed && !args->has("--spp") ? kMaxSpp : *spp;
    util::Timer passes;
    do {
        auto status = (*session)->renderPass();
        if (!status)
            return reportError(status.error());
    } while ((*session)->samplesPerPixel() < maxSpp && (!timed || passes.seconds() < *seconds));

    auto image = (*session)->image();
    if (!image)
        return reportError(image.error());
    auto written = scene::writeImage(*output, *image, scene->camera.exposureEv);
    if (!written)
        return reportError(written.error());
    render::RenderStats stats = (*session)->stats();
    std::printf("wrote %s (%dx%d, %d spp, %s, %.3f s per pass)\n", output->c_str(), options.width,
                options.height, stats.samplesPerPixel, stats.deviceName.c_str(),
                stats.samplesPerPixel ? stats.timings.passSeconds / stats.samplesPerPixel : 0.0);
    if (stats.validationMessages > 0)
        std::fprintf(stderr, "warning: %d Vulkan validation messages\n", stats.validationMessages);
    if (auto reportPath = args->value("--report")) {
        auto ok = scene::writeFileAtomic(
            *reportPath, reportJson(scenePath, *output, options, stats,
                                   scene->lighting.lights.size(), total.seconds()));
        if (!ok)
            return reportError(ok.error());
        std::printf("wrote %s\n", reportPath->c_str());
    }
    return 0;
}

} // namespace

int runRender(const std::vector<std::string>& args) {
    return run(args);
}

} // namespace wavelit::cli
