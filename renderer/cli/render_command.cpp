// `wavelit-cli render SCENE -o OUT.exr|png [--spp N] [--time SECONDS] [--sampler NAME]
//  [--width W --height H] [--seed S] [--bounces B] [--device auto|cpu|vulkan] [--report R.json]
//  [--trace-outliers N --outliers OUT.json] [--also OUT2.exr|png] [--passes FIRST:COUNT] [--mpi]`
//  (the outlier tracer: render/reference/outlier_tracer.h; --also writes the same image a second
//  time, e.g. a PNG preview beside the EXR, without rendering it twice; --passes renders passes
//  FIRST..FIRST+COUNT-1 only, a part for `merge`; --mpi splits the passes over the ranks of an
//  `mpirun` job: docs/farm.md). Every EXR carries the "wavelit:*" attributes of partial_render.h.
// (architecture.md §6). Size and bounces default to the scene's render settings. Passes run until --spp
// is reached or --time has elapsed (both: whichever comes first; neither: kDefaultSpp); --time
// counts from the end of the first pass, which on lavapipe includes the kernel's compile (up to
// ~15 s with a cold shader cache, the state of every fresh machine). PNG output
// applies the camera's exposure (display transform); EXR stores linear radiance. --report writes
// the options, timings, choices with their reasons and the sampler tables built (sizes, build
// times; docs/file-formats.md "Render report"). Exit codes: 0 success, 1 bad input (message
// names the file), 2 bad usage.
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/light_group_output.h"
#include "cli/mpi_job.h"
#include "cli/partial_render.h"
#include "cli/pass_plan.h"
#include "cli/render_flags.h"
#include "render/sampling/direction_sampler.h"
#include "render/reference/outlier_tracer.h"
#include "render/session/render_session.h"
#include "render/sampling/sampler_tables_cache.h"
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
#include <optional>
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

const char* productModeName(const render::MaterialProductTables* t) {
    if (!t)
        return "none";
    switch (t->policy().mode) {
    case render::ProductMode::Product: return "product";
    case render::ProductMode::BsdfLobe: return "bsdf-lobe";
    case render::ProductMode::EnvMis: return "env-mis";
    }
    return "none";
}

// The level of the product both path tracers form per hit (ProductBuild::Tracer); 0 without one.
int tracerProductLevel(const render::MaterialProductTables* t) {
    return t && t->policy().mode == render::ProductMode::Product
               ? render::tracerProductLevel(t->policy())
               : 0;
}

// The direction samplers' tables (architecture.md §7: what was built for this scene and why), or null
// when the sampler needs none (`bsdf`) or the integrator reports none. Fields:
// docs/file-formats.md "Render report".
std::string samplerTablesJson(const render::RenderStats& s, const scene::Scene& scene) {
    if (!s.samplerTables)
        return "null";
    const render::DirectionSamplerTables& t = *s.samplerTables;
    const render::SamplerEnvironment& env = t.environment();
    std::ostringstream j;
    j.precision(9);
    j << "{\n"
      << "    \"sampler\": \"" << render::samplerKindName(t.kind()) << "\",\n"
      << "    \"environment\": {\"octahedralLevel\": " << env.level()
      << ", \"side\": " << (1 << env.level()) << ", \"bytes\": " << env.bytes()
      << ", \"buildSeconds\": " << env.buildSeconds()
      << ", \"lit\": " << (env.hasLight() ? "true" : "false")
      << ", \"reused\": " << (t.environmentReused() ? "true" : "false") << "},\n"
      << "    \"materials\": [";
    size_t totalBytes = env.bytes(), productCount = 0;
    double totalSeconds = env.buildSeconds();
    for (size_t i = 0; i < t.materialCount(); ++i) {
        const render::MaterialProductTables* p = t.productTables(i);
        const size_t bytes = p ? p->bytes() : 0;
        const std::string reason =
            p ? p->policy().reason
            : t.kind() == render::SamplerKind::Oracle
                ? std::string("the oracle builds a dense product per hit (CPU 128^2; Vulkan 32^2 "
                              "env-weighted + 2 refinement levels): no per-material tables")
                : std::string("the ") + render::samplerKindName(t.kind()) +
                      " sampler needs no per-material tables";
        j << (i ? ",\n" : "\n") << "      {\"name\": \"" << jsonEscape(t.material(i).name)
          << "\", \"mode\": \"" << productModeName(p) << "\", \"reason\": \"" << jsonEscape(reason)
          << "\", \"binLevel\": " << (p ? p->policy().binLevel : 0)
          << ", \"productLevel\": " << (p ? p->policy().productLevel : 0)
          << ", \"tracerProductLevel\": " << tracerProductLevel(p)
          << ", \"envKeep\": " << (p ? p->policy().envKeep : 0)
          << ", \"brdfKeep\": " << (p ? p->policy().brdfKeep : 0)
          << ", \"factorCount\": " << (p ? p->factorCount() : 0)
          << ", \"bytes\": " << bytes
          << ", \"buildSeconds\": " << (p ? p->buildSeconds() : 0.0)
          << ", \"reused\": " << (t.productTablesReused(i) ? "true" : "false") << "}";
        if (p) {
            totalBytes += bytes;
            totalSeconds += p->buildSeconds();
            ++productCount;
        }
    }
    j << "\n    ],\n    \"unusedMaterials\": [";
    const std::vector<bool> used = render::materialsInUse(scene);
    bool first = true;
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (!used[i]) {
            j << (first ? "" : ", ") << "\"" << jsonEscape(scene.materials[i].name) << "\"";
            first = false;
        }
    const render::SamplerTablesRebuilds& r = s.samplerRebuilds;
    j << "],\n"
      << "    \"totals\": {\"bytes\": " << totalBytes << ", \"buildSeconds\": " << totalSeconds
      << ", \"productTables\": " << productCount << "},\n"
      << "    \"rebuilds\": {\"environmentBuilds\": " << r.environmentBuilds
      << ", \"environmentReuses\": " << r.environmentReuses
      << ", \"environmentRotations\": " << r.environmentRotations
      << ", \"materialBuilds\": " << r.materialBuilds
      << ", \"materialReuses\": " << r.materialReuses << "}\n"
      << "  }";
    return j.str();
}

// What the session's last scene update rebuilt and uploaded (architecture.md §5.B "What an edit
// rebuilds"); for a render from a file that is the first upload of everything.
std::string updateJson(const render::UpdateCounts& c) {
    std::ostringstream j;
    j << "{\"summary\": \"" << jsonEscape(render::describeUpdate(c)) << "\", \"bvhBuilds\": "
      << c.bvhBuilds << ", \"bvhRefits\": " << c.bvhRefits
      << ", \"samplerTableBuilds\": " << c.samplerTableBuilds
      << ", \"samplerTablesTurned\": " << c.samplerTablesTurned << ", \"uploads\": {\"geometry\": "
      << c.geometryUploads << ", \"lights\": " << c.lightUploads << ", \"materials\": "
      << c.materialUploads << ", \"envTexels\": " << c.envTexelUploads
      << ", \"samplerTables\": " << c.samplerTableUploads << ", \"params\": " << c.paramUploads
      << "}}";
    return j.str();
}

std::string reportJson(const std::string& scenePath, const std::string& output,
                       const render::RenderOptions& o, bool samplerFromFlag,
                       const render::RenderStats& s, const scene::Scene& scene,
                       double totalSeconds) {
    const size_t lightCount = scene.lighting.lights.size();
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
      << "    \"productCacheBytes\": " << s.timings.productCacheBytes << ",\n"
      << "    \"totalSeconds\": " << totalSeconds << "\n"
      << "  },\n"
      << "  \"lastUpdate\": " << updateJson(s.lastUpdate) << ",\n"
      << "  \"choices\": [\n"
      << "    {\"what\": \"sampler\", \"value\": \"" << render::samplerKindName(o.sampler)
      << "\", \"reason\": \""
      << (samplerFromFlag ? "chosen with --sampler" : "the default: no --sampler given") << "\"}";
    // Both tracers render analytic lights the same way (docs/estimator.md "Analytic lights").
    if (lightCount > 0)
        j << ",\n    {\"what\": \"analytic lights\", \"value\": \"nee+mis\", "
             "\"reason\": \""
          << lightCount
          << " light(s): next-event estimation, uniform selection, power-heuristic MIS with "
             "BSDF sampling\"}";
    j << "\n"
      << "  ],\n"
      << "  \"samplerTables\": " << samplerTablesJson(s, scene) << "\n"
      << "}\n";
    return j.str();
}

using util::lowerExtension;

int run(const std::vector<std::string>& argv, std::unique_ptr<MpiJob>& mpi) {
    std::set<std::string> flags = renderValueFlags();
    flags.insert({"-o", "--also", "--spp", "--time", "--report", "--trace-outliers", "--outliers",
                  "--passes"});
    auto args = Args::parse(argv, flags, {"--mpi", "--light-groups"});
    if (!args)
        return reportError(args.error());
    if (args->positional().size() != 1)
        return reportError(makeError(ErrorKind::Usage, "", "render needs exactly one SCENE file"));
    auto output = args->value("-o");
    if (!output)
        return reportError(makeError(ErrorKind::Usage, "", "render needs -o OUT.exr|png"));
    // -o, then --also: the files the one rendered image is written to.
    std::vector<std::string> outputs{*output};
    if (auto also = args->value("--also"))
        outputs.push_back(*also);
    for (const std::string& path : outputs) {
        const std::string ext = lowerExtension(path);
        if (ext != ".exr" && ext != ".png")
            return reportError(
                makeError(ErrorKind::Usage, path, "output must end in .exr or .png"));
    }
    if (auto groups = checkLightGroupFlags(*args, *output); !groups)
        return reportError(groups.error());
    auto spp = args->intValue("--spp", kDefaultSpp, 1, kMaxSpp);
    auto seconds = args->doubleValue("--time", 0.0, 0.0, 1e7);
    if (!spp)
        return reportError(spp.error());
    if (!seconds)
        return reportError(seconds.error());
    auto outlierCount = args->intValue("--trace-outliers", 0, 1, 100000);
    if (!outlierCount)
        return reportError(outlierCount.error());
    if (args->has("--trace-outliers") != args->has("--outliers"))
        return reportError(makeError(ErrorKind::Usage, "",
                                     "--trace-outliers N and --outliers OUT.json go together"));
    // Usage errors in the shared render flags surface before the scene is loaded.
    if (auto early = renderOptionsFromArgs(*args, scene::RenderDefaults{}); !early)
        return reportError(early.error());
    auto range = fixedPasses(*args, *spp, kMaxSpp, *output);
    if (!range)
        return reportError(range.error());
    PassRange local = range->value_or(PassRange{});
    if (args->has("--mpi")) {
        auto job = MpiJob::start();
        if (!job)
            return reportError(job.error());
        mpi = std::move(job).value();
        local = shareOfPasses(**range, mpi->rank(), mpi->size());
        if (local.count == 0)
            return reportError(makeError(ErrorKind::Usage, "",
                                         "--mpi: " + std::to_string((*range)->count) +
                                             " passes for " + std::to_string(mpi->size()) +
                                             " ranks: give each rank one pass at least"));
    }

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
    options.firstPass = local.first;
    options.lightGroups = args->has("--light-groups");
    if (options.lightGroups) // memory said up front (docs/lightmix.md)
        std::printf("%s\n", describeLightGroups(render::lightGroupsOf(*scene), options.width,
                                                options.height).c_str());

    util::Timer total;
    auto session = render::RenderSession::create(*scene, options);
    if (!session)
        return reportError(session.error());
    const bool timed = args->has("--time");
    const int maxSpp = *range ? local.count : timed && !args->has("--spp") ? kMaxSpp : *spp;
    // The clock of --time starts after the first pass: lavapipe compiles the kernel during its
    // first dispatch, and a budget that counted that compile left a fresh machine one pass.
    std::optional<util::Timer> passes;
    // The outlier tracer (issue 20) reads the image after every pass: each pass's sample is the
    // running sum's increment, whatever the device.
    std::optional<render::OutlierMonitor> monitor;
    if (args->has("--trace-outliers"))
        monitor.emplace(options.width, options.height, *outlierCount);
    do {
        auto status = (*session)->renderPass();
        if (!status)
            return reportError(status.error());
        if (monitor) {
            auto mean = (*session)->image();
            if (!mean)
                return reportError(mean.error());
            monitor->addPass(*mean);
        }
        if (!passes) passes.emplace();
    } while ((*session)->samplesPerPixel() < maxSpp && (!timed || passes->seconds() < *seconds));

    auto image = (*session)->image();
    if (!image)
        return reportError(image.error());
    render::RenderStats stats = (*session)->stats();
    if (stats.validationMessages > 0)
        std::fprintf(stderr, "warning: %d Vulkan validation messages\n", stats.validationMessages);
    if (mpi) {
        image = meanOverRanks(*mpi, *image, local.count, (*range)->count);
        if (!image)
            return reportError(image.error());
        if (mpi->rank() != 0)
            return 0; // rank 0 writes the file
    }
    const std::vector<PassRange> rendered{range->value_or(PassRange{0, stats.samplesPerPixel})};
    const scene::ExrAttributes attributes =
        renderAttributes(renderIdentity(*scene, scenePath, options, stats.deviceName), rendered);
    for (const std::string& path : outputs)
        if (auto written = options.lightGroups && lowerExtension(path) == ".exr"
                               ? writeLightGroupExr(path, **session, *image, attributes)
                               : scene::writeImage(path, *image, scene->camera.exposureEv,
                                                   attributes);
            !written)
            return reportError(written.error());
    const std::string ranks =
        mpi ? " over " + std::to_string(mpi->size()) + (mpi->size() == 1 ? " rank" : " ranks") : "";
    std::printf("wrote %s (%dx%d, %d spp, passes %s%s, %s, %.3f s per pass)\n", output->c_str(),
                options.width, options.height, rendered[0].count,
                formatPassRanges(rendered).c_str(), ranks.c_str(), stats.deviceName.c_str(),
                stats.samplesPerPixel ? stats.timings.passSeconds / stats.samplesPerPixel : 0.0);
    if (monitor) {
        std::vector<render::OutlierSample> outliers = monitor->outliers();
        for (render::OutlierSample& o : outliers)
            o.pass += options.firstPass; // the monitor counts this render's passes from 0
        auto paths = render::traceOutlierPaths(*scene, options, outliers);
        if (!paths)
            return reportError(paths.error());
        const std::string outliersPath = *args->value("--outliers");
        auto ok = scene::writeFileAtomic(
            outliersPath, render::outliersJson(options, stats.deviceName, monitor->passes(),
                                               outliers, *paths, *image));
        if (!ok)
            return reportError(ok.error());
        std::printf("wrote %s (%zu outliers)\n", outliersPath.c_str(), outliers.size());
    }
    if (auto reportPath = args->value("--report")) {
        auto ok = scene::writeFileAtomic(
            *reportPath, reportJson(scenePath, *output, options, args->has("--sampler"), stats,
                                   *scene, total.seconds()));
        if (!ok)
            return reportError(ok.error());
        std::printf("wrote %s\n", reportPath->c_str());
    }
    return 0;
}

} // namespace

int runRender(const std::vector<std::string>& args) {
    std::unique_ptr<MpiJob> mpi;
    const int code = run(args, mpi);
    if (code != 0 && mpi && mpi->size() > 1)
        mpi->abort(code); // the other ranks may be waiting for this one's sums
    return code;
}

} // namespace wavelit::cli
