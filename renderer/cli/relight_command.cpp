// `wavelit-cli relight SCENE --edits EDITS.json --out DIR --report R.json [--reference-spp N]
//  [--width W --height H] [--preview PW] [--level N|auto] [--keep K] [--threads T] [--skip-full-rebuild]
//  [--coarse-level N]`
// The relighting preview (docs/relighting.md, architecture.md §5.A) of SCENE after each edit of
// EDITS.json (relight/edit_list.h), applied in order: DIR/edit_<i>.exr is the preview after edit
// i (linear radiance at the render size: the scene's, or --width/--height), and the report lists
// per edit what it rebuilt and what it cost against a from-scratch build of the edited scene;
// with --reference-spp N also relRMSE = sqrt(relative MSE, render/session/image_metrics.h) against
// the CPU tracer's direct lighting (bounces 1, N spp, MIS sampler) of the edited scene.
// --preview: preview points per row (default 256, at most the output width; the height follows
// the aspect); --level: the sphere grid 2^N squared (default auto: 32², 64² / 128² for a lobe narrower
// than half a 32² / 64² texel, relight/sphere_level.h); --keep: Haar coefficients of T per point
// (default 128); --skip-full-rebuild: no from-scratch build per edit (fullRebuildMs null; for latency profiles);
// --coarse-level N: also the coarse-to-fine first answer (relight/coarse_to_fine.h) from a preview
// on the 2^N grid (--coarse-stride S: on every S-th preview pixel per axis), applied before the
// full one: DIR/edit_<i>_coarse.exr and per edit coarseMs, coarseImageMs (and coarseRelRMSE
// with a reference); and the corrected first answer (relight/first_answer.h, approximate):
// DIR/edit_<i>_first.exr, firstMs / firstCpuMs (the coarse edit, deferring the moved object's
// own points, + the correction), firstImageMs, and coarseVsPreviewRelRMSE / firstVsPreviewRelRMSE
// against this edit's exact preview (the coarse image with those points stale). A material edit's
// first answer is instead the full preview's untruncated one (RelightPreview::materialFirstAnswer,
// docs/relighting.md §7.0g): "firstAnswer": "untruncated", firstPointsTouched — as the editor's
// coarse-to-fine; where an edited material's lobe is narrower than a texel it is averaged over
// 2 x 2 directions a texel, "untruncated, coarse lobes" (§7.0h), unless --first-untruncated-narrow
// (4 x 4, as the full answer); with a reference every first answer also has firstRelRMSE.
// --shadow-field: translation drags of the first object the list translates go through its
// shadow field (relight/shadow_field.h, docs/relighting.md §7.0e; --field-shells N,
// --field-directions L (2^L squared per shell), --field-inner R / --field-outer R (shell radii over
// the bounding radius), --field-nearest (the nearest sample, not the 8-sample blend),
// --field-carry-own (the moved object's own points carry their visibility from the drag start's
// nearest point of it: ShadowFieldSettings::reuseOwnStates, §7.0j; --field-lobe-cut C sums their
// narrow lobes within C cap angles of the mirror direction only, carriedLobeCut, §7.0k)): the
// report's "shadowField" block says what the field and the per-point caches cost, and each edit's
// "method" ("shadowField" or "exact"), pointsRebuilt, fieldFallbacks, selfMasksReused,
// statesCarried and cacheMs;
// --field-check also keeps an exact preview beside it and reports each edit's fieldVsExactRelRMSE
// (the field's image against the exact, ray-cast one).
// Exit codes: 0 success, 1 bad input (message names the file), 2 bad usage.
#include "cli/args.h"
#include "cli/commands.h"
#include "relight/coarse_to_fine.h"
#include "relight/first_answer.h"
#include "relight/edit_list.h"
#include "relight/relight_preview.h"
#include "relight/sphere_level.h"
#include "render/session/image_metrics.h"
#include "render/session/render_session.h"
#include "scene/atomic_file.h"
#include "scene/image_io.h"
#include "scene/scene_io.h"
#include "util/image_compare.h"
#include "util/timer.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <optional>

namespace wavelit::cli {
namespace {

using util::ErrorKind;
using util::makeError;

// Preview points per row unless --preview says otherwise (docs/relighting.md §1, measured): one
// point per output pixel up to 256 columns (nearest-point upsampling of 2x already costs 5x in
// relRMSE on ring_on_ground), and no more than 256, where a point set costs ~2.4 KB a point and
// seconds to build.
constexpr int kDefaultPreviewWidth = 256;

util::Result<util::ImageRGB> directLightingReference(const scene::Scene& scene, int width, int height, int spp) {
    render::RenderOptions options;
    options.width = width;
    options.height = height;
    options.bounces = 1;
    options.device = render::DeviceChoice::Cpu;
    options.sampler = render::SamplerKind::Mis;
    auto session = render::RenderSession::create(scene, options);
    if (!session) return session.error();
    while ((*session)->samplesPerPixel() < spp)
        if (auto st = (*session)->renderPass(); !st) return st.error();
    return (*session)->image();
}

double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Largest |a - b| / max(|b|, 1e-6) over pixels and channels: the incremental preview against
// the from-scratch one (architecture.md §8: cached products against full recomputation).
} // namespace

int runRelight(const std::vector<std::string>& argv) {
    auto args = Args::parse(argv, {"--edits", "--out", "--report", "--reference-spp", "--width",
                                   "--height", "--preview", "--level", "--keep", "--threads", "--coarse-level", "--coarse-stride",
                                   "--field-shells", "--field-directions", "--field-inner", "--field-outer",
                                   "--field-lobe-cut"},
                            {"--skip-full-rebuild", "--shadow-field", "--field-check", "--field-nearest", "--field-carry-own",
                             "--first-untruncated-narrow"});
    if (!args) return reportError(args.error());
    if (args->positional().size() != 1)
        return reportError(makeError(ErrorKind::Usage, "", "relight needs exactly one SCENE"));
    for (const char* flag : {"--edits", "--out", "--report"})
        if (!args->value(flag))
            return reportError(makeError(ErrorKind::Usage, "", std::string("relight needs ") + flag));
    auto refSpp = args->intValue("--reference-spp", 0, 1, 1 << 20);
    // --level auto (the default): the grid the scene's materials need (relight/sphere_level.h).
    const bool autoLevel = !args->value("--level") || *args->value("--level") == "auto";
    auto level = autoLevel ? util::Result<int>(5) : args->intValue("--level", 5, 1, 7);
    auto keep = args->intValue("--keep", 128, 1, 1 << 14);
    auto threads = args->intValue("--threads", 2, 1, 256);
    auto previewWidth = args->intValue("--preview", kDefaultPreviewWidth, 1, 4096);
    auto coarseLevel = args->intValue("--coarse-level", 0, 1, 7); // 0: no coarse answer
    auto coarseStride = args->intValue("--coarse-stride", 1, 1, 16);
    auto fieldShells = args->intValue("--field-shells", 32, 1, 1024);
    auto fieldDirections = args->intValue("--field-directions", 5, 1, 7);
    for (const auto* r : {&refSpp, &level, &keep, &threads, &previewWidth, &coarseLevel, &coarseStride, &fieldShells,
                          &fieldDirections})
        if (!*r) return reportError(r->error());
    relight::ShadowFieldSettings fieldSettings;
    fieldSettings.shells = *fieldShells;
    fieldSettings.directionLevel = *fieldDirections;
    fieldSettings.interpolate = !args->has("--field-nearest");
    fieldSettings.reuseOwnStates = args->has("--field-carry-own");
    for (auto [flag, target] : {std::pair{"--field-inner", &fieldSettings.innerRatio},
                                std::pair{"--field-outer", &fieldSettings.outerRatio},
                                std::pair{"--field-lobe-cut", &fieldSettings.carriedLobeCut}})
        if (auto v = args->value(flag)) {
            char* end = nullptr;
            const float x = std::strtof(v->c_str(), &end);
            if (!end || *end || !(x > 0.0f) || !(x < 1e4f))
                return reportError(makeError(ErrorKind::Usage, "", std::string(flag) + " needs a positive number"));
            *target = x;
        }

    // --first-untruncated-narrow: the untruncated material first answer for narrow lobes too
    // (the editor's coarse-to-fine takes the corrected one there; for measuring, §7.0g).
    const bool untruncatedNarrow = args->has("--first-untruncated-narrow");
    const std::string scenePath = args->positional()[0];
    auto loaded = scene::loadScene(scenePath);
    if (!loaded) {
        util::Error e = loaded.error();
        if (e.file.empty()) e.file = scenePath;
        return reportError(e);
    }
    scene::Scene scene = std::move(loaded).value();
    auto width = args->intValue("--width", scene.render.width, 1, 16384);
    auto height = args->intValue("--height", scene.render.height, 1, 16384);
    if (!width) return reportError(width.error());
    if (!height) return reportError(height.error());
    auto edits = relight::readEditList(*args->value("--edits"), scene);
    if (!edits) return reportError(edits.error());

    relight::RelightSettings settings;
    settings.width = std::min(*previewWidth, *width);
    settings.height = std::max(1, int(std::lround(double(settings.width) * *height / *width)));
    relight::SphereLevelChoice levelChoice{*level, "set by --level"};
    if (autoLevel) levelChoice = relight::chooseSphereLevel(scene);
    settings.level = levelChoice.level;
    settings.keep = size_t(*keep);
    settings.threads = *threads;
    const std::filesystem::path out(*args->value("--out"));
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) return reportError(makeError(ErrorKind::Io, out.string(), "cannot create the folder: " + ec.message()));

    util::Timer buildTimer;
    auto preview = relight::RelightPreview::create(scene, settings);
    if (!preview) return reportError(preview.error());
    const double buildMs = buildTimer.milliseconds();
    // The coarse-to-fine first answer: the same preview on a coarser grid, edited first.
    std::unique_ptr<relight::RelightPreview> coarse;
    const relight::RelightSettings coarseSettings =
        relight::CoarseToFinePreview::coarseSettings(settings, *coarseLevel, *coarseStride);
    double coarseBuildMs = 0.0;
    if (*coarseLevel > 0) {
        util::Timer coarseTimer;
        auto built = relight::RelightPreview::create(scene, coarseSettings);
        if (!built) return reportError(built.error());
        coarse = std::move(built).value();
        coarseBuildMs = coarseTimer.milliseconds();
    }
    // The shadow field of the first object the edit list translates (--shadow-field).
    std::unique_ptr<relight::RelightPreview> exact; // --field-check: the ray-cast preview beside it
    nlohmann::ordered_json fieldReport(nullptr);
    if (args->has("--shadow-field")) {
        std::optional<size_t> object;
        for (const relight::PlannedEdit& edit : *edits)
            for (const scene::Edit& change : edit.changes.edits())
                if (const auto* pe = std::get_if<scene::PropertyEdit>(&change);
                    !object && pe && pe->entity.kind == scene::EntityKind::Object && pe->property == "translation")
                    for (size_t j = 0; j < scene.objects.size(); ++j)
                        if (scene.objects[j].id == pe->entity.id) object = j;
        if (object) {
            if (args->has("--field-check")) {
                auto built = relight::RelightPreview::create(scene, settings);
                if (!built) return reportError(built.error());
                exact = std::move(built).value();
            }
            const relight::ShadowFieldInfo info = (*preview)->enableShadowField(*object, fieldSettings);
            fieldReport = {{"object", scene.objects[*object].name}, {"shells", fieldSettings.shells},
                           {"directionSide", 1 << fieldSettings.directionLevel},
                           {"interpolate", fieldSettings.interpolate},
                           {"carryOwnStates", fieldSettings.reuseOwnStates},
                           {"carriedLobeCut", fieldSettings.carriedLobeCut},
                           {"insideSamples", (*preview)->shadowField()->insideSamples()},
                           {"innerRatio", fieldSettings.innerRatio}, {"outerRatio", fieldSettings.outerRatio},
                           {"fieldMs", info.fieldMs}, {"fieldBytes", info.fieldBytes}, {"cacheMs", info.cacheMs},
                           {"cachedPoints", info.cachedPoints},
                           {"cacheBytesPerPoint", info.cachedPoints ? double(info.cacheBytes) / double(info.cachedPoints) : 0.0}};
        }
    }
    nlohmann::ordered_json report;
    report["scene"] = scenePath;
    report["preview"] = {{"width", settings.width}, {"height", settings.height},
                         {"sphereSide", 1 << settings.level}, {"sphereReason", levelChoice.reason},
                         {"keep", settings.keep},
                         {"threads", settings.threads}, {"points", (*preview)->hitCount()},
                         {"buildMs", buildMs},
                         {"bytesPerPoint", (*preview)->hitCount() ? double((*preview)->stateBytes()) / double((*preview)->hitCount()) : 0.0}};
    if (coarse)
        report["coarse"] = {{"sphereSide", 1 << coarseSettings.level}, {"keep", coarseSettings.keep},
                            {"width", coarseSettings.width}, {"height", coarseSettings.height},
                            {"buildMs", coarseBuildMs},
                            {"bytesPerPoint", coarse->hitCount() ? double(coarse->stateBytes()) / double(coarse->hitCount()) : 0.0}};
    report["shadowField"] = fieldReport;
    report["reference"] = *refSpp > 0 ? nlohmann::ordered_json{{"device", "cpu"}, {"sampler", "mis"}, {"bounces", 1}, {"spp", *refSpp}}
                                      : nlohmann::ordered_json(nullptr);
    report["edits"] = nlohmann::ordered_json::array();
    for (size_t i = 0; i < edits->size(); ++i) {
        const relight::PlannedEdit& edit = (*edits)[i];
        if (auto st = edit.changes.apply(scene); !st) return reportError(st.error());
        nlohmann::ordered_json e;
        std::optional<util::ImageRGB> coarseImage, firstImage;
        if (coarse) {
            // The corrected first answer's inputs, taken when the full preview was last up to date
            // (here: before this edit); the editor takes them after applyFine, off the drag.
            const relight::FirstAnswerBase base = relight::firstAnswerBase(**preview, *coarse);
            // A material edit: the full preview's untruncated answer (no T rebuilt), as
            // CoarseToFinePreview::applyCoarse takes it; the coarse preview gets the edit after
            // it (the editor's gets it with the full update), timed on its own (coarseMs).
            util::Timer materialTimer;
            const double materialCpuBefore = processCpuMs();
            auto material = (*preview)->materialFirstAnswer(
                scene, edit.changes,
                untruncatedNarrow ? relight::LobeAverage::Full : relight::LobeAverage::Coarse);
            if (material) {
                util::Timer firstTimer;
                firstImage = relight::nearestScaled(material->image, *width, *height);
                e["firstImageMs"] = firstTimer.milliseconds();
                e["firstMs"] = materialTimer.milliseconds();
                e["firstCpuMs"] = processCpuMs() - materialCpuBefore;
                e["firstAnswer"] = material->coarseLobes
                                       ? relight::CoarseToFinePreview::kUntruncatedCoarseLobes
                                       : "untruncated";
                e["firstPointsTouched"] = material->pointsTouched;
            }
            util::Timer coarseTimer;
            const double cpuBefore = processCpuMs();
            coarse->applyChanges(scene, edit.changes, /*deferMovedObjects=*/true);
            e["coarseMs"] = coarseTimer.milliseconds();
            if (!material) {
                util::Timer firstTimer;
                firstImage = relight::correctedFirstAnswer(base, *coarse, *width, *height);
                e["firstImageMs"] = firstTimer.milliseconds();
                e["firstMs"] = coarseTimer.milliseconds(); // the coarse edit + the corrected image
                e["firstCpuMs"] = processCpuMs() - cpuBefore;
                e["firstAnswer"] = "approximate";
            }
            const std::string firstFile = (out / ("edit_" + std::to_string(i) + "_first.exr")).string();
            if (auto st = scene::writeExr(firstFile, *firstImage); !st) return reportError(st.error());
            util::Timer coarseImageTimer;
            coarseImage = coarse->image(*width, *height);
            e["coarseImageMs"] = coarseImageTimer.milliseconds();
            const std::string coarseFile = (out / ("edit_" + std::to_string(i) + "_coarse.exr")).string();
            if (auto st = scene::writeExr(coarseFile, *coarseImage); !st) return reportError(st.error());
        }
        util::Timer incremental;
        const double cpuBefore = processCpuMs();
        const relight::EditSummary summary = (*preview)->applyChanges(scene, edit.changes);
        const double incrementalMs = incremental.milliseconds();
        const double incrementalCpuMs = processCpuMs() - cpuBefore;
        if (coarse) coarse->applyChanges(scene, scene::ChangeSet{}); // its deferred points, as applyFine does
        util::Timer imageTimer;
        const util::ImageRGB image = (*preview)->image(*width, *height);
        const double imageMs = imageTimer.milliseconds();
        if (firstImage) { // the approximate answers against this edit's exact preview
            e["coarseVsPreviewRelRMSE"] = relight::relativeRmse(*coarseImage, image);
            e["firstVsPreviewRelRMSE"] = relight::relativeRmse(*firstImage, image);
        }
        const std::string file = (out / ("edit_" + std::to_string(i) + ".exr")).string();
        if (auto st = scene::writeExr(file, image); !st) return reportError(st.error());
        const bool skipFull = args->has("--skip-full-rebuild");
        util::Timer full;
        auto scratch = skipFull ? util::Result<std::unique_ptr<relight::RelightPreview>>(nullptr)
                                : relight::RelightPreview::create(scene, settings);
        if (!scratch) return reportError(scratch.error());
        const double fullMs = full.milliseconds();
        e["entity"] = edit.entity;
        e["property"] = edit.property;
        e["kind"] = summary.kind;
        e["factorsRebuilt"] = summary.factorsRebuilt;
        e["pointsTouched"] = summary.pointsTouched;
        e["incrementalMs"] = incrementalMs;
        // CPU time of every thread of the process during applyChanges (its workers; nothing else
        // runs meanwhile): steadier than wall time on a loaded machine.
        e["incrementalCpuMs"] = incrementalCpuMs;
        e["fullRebuildMs"] = skipFull ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(fullMs);
        e["sharedFactorsMs"] = summary.sharedMs;
        e["perPointMs"] = summary.pointsMs;
        e["imageMs"] = imageMs; // summing the cached terms into the output image (not in incrementalMs)
        if (!fieldReport.is_null()) {
            e["method"] = summary.method.empty() ? "exact" : summary.method;
            e["pointsRebuilt"] = summary.pointsRebuilt;
            e["fieldFallbacks"] = summary.fieldFallbacks;
            e["selfMasksReused"] = summary.selfMasksReused;
            e["statesCarried"] = summary.statesCarried;
            e["cacheMs"] = summary.cacheMs;
            e["rebuiltCpuMs"] = summary.rebuiltCpuMs; // of incrementalCpuMs: the hit-changed points
        }
        if (exact) {
            exact->applyChanges(scene, edit.changes);
            e["fieldVsExactRelRMSE"] = relight::relativeRmse(image, exact->image(*width, *height));
        }
        e["maxRelDiffVsFullRebuild"] = skipFull ? nlohmann::ordered_json(nullptr)
                                                : nlohmann::ordered_json(util::maxRelativeDifference((*preview)->image(), (*scratch)->image()));
        if (*refSpp > 0) {
            auto reference = directLightingReference(scene, *width, *height, *refSpp);
            if (!reference) return reportError(reference.error());
            e["relRMSE"] = std::sqrt(render::relativeMse(image, *reference));
            if (coarseImage) e["coarseRelRMSE"] = std::sqrt(render::relativeMse(*coarseImage, *reference));
            if (firstImage) e["firstRelRMSE"] = std::sqrt(render::relativeMse(*firstImage, *reference));
            e["meanPreview"] = render::meanValue(image);
            e["meanReference"] = render::meanValue(*reference);
            if (const char* keepRef = std::getenv("WAVELIT_RELIGHT_KEEP_REFERENCE"); keepRef && *keepRef == '1')
                (void)scene::writeExr((out / ("reference_" + std::to_string(i) + ".exr")).string(), *reference);
        } else {
            e["relRMSE"] = nullptr;
        }
        report["edits"].push_back(std::move(e));
        std::printf("edit %zu (%s %s): %s, %zu points, %.1f ms (full rebuild %s ms) -> %s\n", i,
                    edit.entity.c_str(), edit.property.c_str(), summary.kind.c_str(), summary.pointsTouched,
                    incrementalMs, skipFull ? "-" : std::to_string(fullMs).c_str(), file.c_str());
    }
    if (auto st = scene::writeFileAtomic(*args->value("--report"), report.dump(2) + "\n"); !st)
        return reportError(st.error());
    return 0;
}

} // namespace wavelit::cli
