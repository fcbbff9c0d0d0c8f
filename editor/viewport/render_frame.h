// What crosses between the UI thread and the render thread, both ways, by value through queued
// signals. Images are shared immutable (shared_ptr<const>, and QImage's implicit sharing): the
// render thread never touches an image after publishing it, so neither side needs a lock.
#pragma once

#include "render/session/render_options.h"
#include "scene/change_set.h"
#include "scene/scene.h"
#include "util/image.h"

#include <QImage>
#include <QMetaType>
#include <QString>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wavelit::editor {

// One render request: a scene snapshot and the options to render it with. Each request gets a
// new generation so frames of an older scene still in the queue are recognised and dropped.
struct RenderJob {
    std::shared_ptr<const scene::Scene> scene;
    // The scene file relative asset paths start from; assets an edit dropped (a new mesh or
    // environment path) are loaded from it on the render thread, never on the UI thread.
    std::string scenePath;
    render::RenderOptions options;
    int maxSamplesPerPixel = 0; // stop (idle) once reached; 0 = progressive forever
    quint64 generation = 0;
    // An edit (RenderController::renderEdit): what changed since the scene of job
    // `baseGeneration`; the worker applies it when its session holds that scene, else (or when
    // empty) it swaps in the whole scene.
    std::optional<scene::ChangeSet> changes;
    quint64 baseGeneration = 0;
};

// A published frame: the mean linear radiance so far, its display form and the statistics that
// go with it. The render thread tone-maps (tone_map.h) with the exposure it was last given
// (RenderController::setExposure); an exposure change re-publishes the same samples re-mapped.
struct RenderFrame {
    // Who made it: the path tracer at the render size, the path tracer's reduced-resolution draft
    // pass (while a drag lasts), or the relighting preview (relight_worker.h). Scripts see the
    // last two as kind "preview" (docs/scripting.md, app.waitForFrame).
    enum class Kind { PathTraced, Draft, Relight };
    Kind kind = Kind::PathTraced;
    // A relighting preview's corrected first answer during a drag (relight_worker.h): an
    // approximation of the exact preview that follows once the drag pauses (docs/relighting.md
    // §7.0c); false for the exact preview and every path-traced frame.
    bool approximate = false;
    std::shared_ptr<const util::ImageRGB> image;
    QImage display;               // toneMap(*image, displayExposureEv); null without an image
    float displayExposureEv = 0.0f;
    int samplesPerPixel = 0;
    double elapsedSeconds = 0.0; // render time since the last restart
    QString deviceName;
    int validationMessages = 0; // Vulkan validation messages so far (tests require 0)
    QString lastUpdate;         // what the last scene update rebuilt and uploaded (describeUpdate)
    quint64 generation = 0;
    // LightMix (--light-mix): the light-group layers the image was mixed from and the scene they
    // were rendered with (remixBaseScene), so the A/B view (app/lightmix_compare.h) can remix
    // them with other weights; null without light groups.
    std::shared_ptr<const std::vector<util::ImageRGB>> layers;
    std::shared_ptr<const scene::Scene> layersScene;
    // Path traced: the estimated relRMSE of `image` against the converged image (image_metrics.h
    // relativeMse), from two frames of one generation at m < n spp: E|I_n - I_m|^2 is
    // sigma^2 (n - m)/(n m) and the error of I_n is sigma^2/n, so relMSE(I_n) ~= relMSE(I_m vs
    // I_n) * m / (n - m). Negative while unknown (the first frame of a generation).
    double estimatedRelError = -1.0;
    bool last = false; // the render stops after this frame (--max-spp reached)
    // Set by RenderController when the frame is shown: ms from the edit (the render request) to
    // the frame's arrival on the UI thread.
    double msSinceEdit = -1.0;
};

} // namespace wavelit::editor

Q_DECLARE_METATYPE(wavelit::editor::RenderJob)
Q_DECLARE_METATYPE(wavelit::editor::RenderFrame)
