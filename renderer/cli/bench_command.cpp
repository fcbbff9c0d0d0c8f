// `wavelit-cli bench SCENE [--reference REF.exr] [--samplers a,b,..] [--time SECONDS] --out DIR`
// Speed versus error at equal time (architecture.md §8): each sampler renders for the same wall time;
// after passes 1, 2, 4, 8, ... and at the end the RMSE against the reference is recorded.
// Writes DIR/bench.json, DIR/bench.csv, DIR/bench.png (log-log RMSE vs seconds) and
// DIR/<sampler>.exr. Without --reference, a reference is rendered first with the `mis` sampler
// (env NEE + BSDF sampling, the best general-purpose estimator) for 8x the time (said so in
// bench.json: it carries that sampler's own noise). Per sampler bench.json also holds the
// per-sample and per-second figures that docs/performance-bench.md tabulates: relRMSE = RMSE /
// the reference's mean, relRMSE^2 x spp (per-sample variance) and relRMSE^2 x seconds (inverse
// efficiency: lower is better at equal time).
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/convergence_plot.h"
#include "cli/render_flags.h"
#include "render/session/image_metrics.h"
#include "render/session/render_session.h"
#include "scene/image_io.h"
#include "scene/scene_io.h"
#include "util/timer.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace wavelit::cli {

namespace {

using util::ErrorKind;
using util::makeError;

constexpr double kReferenceTimeFactor = 8.0;

struct SamplerRun {
    std::string name;
    std::string skippedReason;
    int samplesPerPixel = 0;
    double seconds = 0.0;
    std::vector<CurvePoint> points;
    std::vector<int> pointSpp; // samples per pixel at each point
};

util::Result<std::vector<std::string>> splitSamplers(const std::string& list) {
    std::vector<std::string> names;
    std::stringstream ss(list);
    for (std::string name; std::getline(ss, name, ',');) {
        if (name.empty()) continue;
        if (auto s = render::parseSamplerKind(name); !s) return s.error();
        names.push_back(name);
    }
    if (names.empty()) return makeError(ErrorKind::Usage, "", "--samplers lists no sampler");
    return names;
}

// Renders until `seconds` of pass time have elapsed (at least one pass); calls `checkpoint` after
// passes 1, 2, 4, ... and after the last one. One pass is rendered and discarded first: lavapipe
// compiles a kernel during its first dispatch (seconds, up to ~15 s with a cold shader cache), and
// an equal-time comparison that counted it would rank the samplers by compile time.
template <typename Checkpoint>
util::Status renderFor(render::RenderSession& session, double seconds, Checkpoint&& checkpoint) {
    if (auto s = session.renderPass(); !s) return s;
    session.resetAccumulation();
    util::Timer timer;
    int nextCheckpoint = 1;
    for (;;) {
        if (auto s = session.renderPass(); !s) return s;
        const int spp = session.samplesPerPixel();
        const bool done = timer.seconds() >= seconds;
        if (spp == nextCheckpoint || done) {
            if (auto s = checkpoint(timer.seconds(), spp); !s) return s;
            if (spp == nextCheckpoint) nextCheckpoint *= 2;
        }
        if (done) return util::okStatus();
    }
}

util::Status writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    if (!out) return makeError(ErrorKind::Io, path.string(), "cannot write");
    return util::okStatus();
}

} // namespace

int runBench(const std::vector<std::string>& argv) {
    std::set<std::string> flags = renderValueFlags();
    flags.insert({"--reference", "--samplers", "--time", "--out"});
    auto args = Args::parse(argv, flags);
    if (!args) return reportError(args.error());
    if (args->positional().size() != 1)
        return reportError(makeError(ErrorKind::Usage, "", "bench takes exactly one SCENE"));
    auto outDir = args->value("--out");
    if (!outDir) return reportError(makeError(ErrorKind::Usage, "", "bench needs --out DIR"));
    auto seconds = args->doubleValue("--time", 10.0, 1e-3, 1e6);
    if (!seconds) return reportError(seconds.error());
    auto samplers = splitSamplers(args->value("--samplers").value_or("uniform,cosine,bsdf,env,mis,wavelet,oracle"));
    if (!samplers) return reportError(samplers.error());

    const std::string scenePath = args->positional()[0];
    auto scene = scene::loadScene(scenePath);
    if (!scene) return reportError(scene.error());
    auto baseOptions = renderOptionsFromArgs(*args, scene->render);
    if (!baseOptions) return reportError(baseOptions.error());

    std::error_code ec;
    std::filesystem::create_directories(*outDir, ec);
    if (ec) return reportError(makeError(ErrorKind::Io, *outDir, "cannot create folder: " + ec.message()));
    const std::filesystem::path dir(*outDir);

    // The reference: given, or rendered now.
    util::ImageRGB reference;
    std::string referenceSource;
    if (auto refPath = args->value("--reference")) {
        auto ref = scene::loadImage(*refPath);
        if (!ref) return reportError(ref.error());
        reference = std::move(ref->image);
        referenceSource = *refPath;
        if (reference.width != baseOptions->width || reference.height != baseOptions->height)
            return reportError(makeError(ErrorKind::Invalid, *refPath,
                "reference is " + std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                " but the render is " + std::to_string(baseOptions->width) + "x" + std::to_string(baseOptions->height)));
    } else {
        render::RenderOptions refOptions = *baseOptions;
        refOptions.sampler = render::SamplerKind::Mis;
        refOptions.seed = baseOptions->seed + 0x5eed;
        auto session = render::RenderSession::create(*scene, refOptions);
        if (!session) return reportError(session.error());
        auto s = renderFor(**session, *seconds * kReferenceTimeFactor,
                           [](double, int) { return util::okStatus(); });
        if (!s) return reportError(s.error());
        auto img = (*session)->image();
        if (!img) return reportError(img.error());
        reference = std::move(img).value();
        referenceSource = "rendered: mis sampler, " + std::to_string((*session)->samplesPerPixel()) + " spp";
        if (auto w = scene::writeExr((dir / "reference.exr").string(), reference); !w) return reportError(w.error());
    }

    std::vector<SamplerRun> runs;
    for (const auto& name : *samplers) {
        SamplerRun run;
        run.name = name;
        render::RenderOptions options = *baseOptions;
        options.sampler = *render::parseSamplerKind(name);
        auto session = render::RenderSession::create(*scene, options);
        if (!session) {
            if (session.error().kind != ErrorKind::Unsupported) return reportError(session.error());
            run.skippedReason = session.error().reason;
            runs.push_back(run);
            continue;
        }
        auto s = renderFor(**session, *seconds, [&](double t, int spp) -> util::Status {
            auto img = (*session)->image();
            if (!img) return img.error();
            run.points.push_back({t, render::rmse(*img, reference)});
            run.pointSpp.push_back(spp);
            run.samplesPerPixel = spp;
            run.seconds = t;
            return util::okStatus();
        });
        if (!s) return reportError(s.error());
        if (auto img = (*session)->image())
            if (auto w = scene::writeExr((dir / (name + ".exr")).string(), *img); !w) return reportError(w.error());
        runs.push_back(run);
    }

    nlohmann::json report;
    report["scene"] = scenePath;
    report["reference"] = referenceSource;
    report["width"] = baseOptions->width;
    report["height"] = baseOptions->height;
    report["seconds_per_sampler"] = *seconds;
    const double referenceMean = render::meanValue(reference);
    report["reference_mean"] = referenceMean;
    std::string csv = "sampler,seconds,spp,rmse\n";
    std::vector<Curve> curves;
    for (const auto& run : runs) {
        nlohmann::json j;
        j["sampler"] = run.name;
        if (!run.skippedReason.empty()) {
            j["skipped"] = run.skippedReason;
        } else {
            j["spp"] = run.samplesPerPixel;
            j["seconds"] = run.seconds;
            const double finalRmse = run.points.empty() ? 0.0 : run.points.back().error;
            j["final_rmse"] = finalRmse;
            j["seconds_per_pass"] = run.samplesPerPixel ? run.seconds / run.samplesPerPixel : 0.0;
            if (referenceMean > 0.0) {
                const double rel2 = (finalRmse / referenceMean) * (finalRmse / referenceMean);
                j["rel_rmse"] = finalRmse / referenceMean;
                j["rel_mse_x_spp"] = rel2 * run.samplesPerPixel;
                j["rel_mse_x_seconds"] = rel2 * run.seconds;
            }
            for (size_t k = 0; k < run.points.size(); ++k) {
                const CurvePoint& p = run.points[k];
                j["curve"].push_back({{"seconds", p.seconds}, {"spp", run.pointSpp[k]}, {"rmse", p.error}});
                std::ostringstream line;
                line << run.name << ',' << p.seconds << ',' << run.pointSpp[k] << ',' << p.error << '\n';
                csv += line.str();
            }
            curves.push_back({run.name, curveColor(run.name), run.points});
        }
        report["samplers"].push_back(j);
        report["legend_order"].push_back(run.name);
    }
    if (auto s = writeText(dir / "bench.json", report.dump(2) + "\n"); !s) return reportError(s.error());
    if (auto s = writeText(dir / "bench.csv", csv); !s) return reportError(s.error());
    if (auto s = scene::writePng((dir / "bench.png").string(), plotConvergence(curves)); !s) return reportError(s.error());
    for (const auto& run : runs) {
        if (run.skippedReason.empty())
            std::printf("%-8s %6d spp in %6.2f s  RMSE %.5g\n", run.name.c_str(), run.samplesPerPixel,
                        run.seconds, run.points.empty() ? 0.0 : run.points.back().error);
        else
            std::printf("%-8s skipped: %s\n", run.name.c_str(), run.skippedReason.c_str());
    }
    std::printf("bench: wrote %s/bench.{json,csv,png}\n", dir.string().c_str());
    return 0;
}

} // namespace wavelit::cli
