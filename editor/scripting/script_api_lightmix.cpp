// AppApi's LightMix calls (docs/scripting.md, docs/lightmix.md): mute and solo as ordinary,
// undoable edits of the lights' `muted` property, the latest frame's update status, Extract sun,
// and the A/B snapshots and split view (app/lightmix_compare.h).
#include "scripting/script_api.h"

#include "app/extract_sun_edit.h"
#include "lightmix/compare_render_context.h"
#include "app/lightmix_compare.h"
#include "app/main_window.h"
#include "app/scene_document.h"
#include "panels/entity_ref.h"
#include "viewport/render_controller.h"

#include "render/session/light_remix.h"
#include "scene/scene_io.h"

#include <QJSEngine>

namespace wavelit::editor {

bool AppApi::setMute(const QString& light, bool muted) {
    return setProperty(light, "muted", QJSValue(muted));
}

bool AppApi::solo(const QString& light) {
    SceneDocument* document = m_window->document();
    auto scene = document->scene();
    if (!scene) return fail("solo: no scene is open");
    auto ref = resolveEntity(*scene, light.toStdString());
    if (!ref) return fail("solo: " + QString::fromStdString(ref.error().message()));
    if (ref->kind != scene::EntityKind::Light) return fail("solo: '" + light + "' is not a light");
    auto status = document->solo(ref->id);
    return status ? true : fail(QString::fromStdString(status.error().message()));
}

QString AppApi::frameStatus() const { return m_window->renderer()->latestFrame().lastUpdate; }

QString AppApi::extractSun() {
    auto name = extractSunEdit(*m_window->document());
    if (!name) {
        fail(QString::fromStdString(name.error().message()));
        return {};
    }
    return QString::fromStdString(*name);
}

bool AppApi::snapshot(const QString& name) {
    auto scene = m_window->document()->scene();
    if (!scene) return fail("snapshot: no scene is open");
    if (name.isEmpty() || name == "current") return fail("snapshot: '" + name + "' cannot name a snapshot");
    m_window->lightMixCompare()->snapshot(name, scene->lighting);
    return true;
}

QJSValue AppApi::compare(const QString& a, const QString& b) {
    SceneDocument* document = m_window->document();
    if (!document->scene()) return fail("compare: no scene is open"), QJSValue();
    LightMixCompare* view = m_window->lightMixCompare();
    std::array<LightMixCompare::Side, 2> sides;
    const std::array<QString, 2> names{a, b};
    for (size_t i = 0; i < 2; ++i) {
        const QString& name = names[i];
        if (name == "current") {
            sides[i] = {name, document->scene()->lighting};
            const scene::LightingSetup atStart = sides[i].lighting;
            sides[i].live = [document, atStart] {
                return document->scene() ? document->scene()->lighting : atStart;
            };
        } else if (auto snap = view->snapshotNamed(name)) {
            sides[i] = {name, *snap};
        } else if (name.endsWith(".wllight")) {
            auto setup = scene::loadLightingSetup(name.toStdString());
            if (!setup) return fail("compare: " + QString::fromStdString(setup.error().message())), QJSValue();
            sides[i] = {name, *setup};
        } else {
            fail("compare: '" + name + "' is neither \"current\", a snapshot (" + view->snapshotNames().join(", ") +
                 ") nor a .wllight file");
            return {};
        }
    }
    const RenderController* renderer = m_window->renderer();
    const RenderFrame& frame = renderer->latestFrame();
    if (!renderer->settings().lightMix)
        return fail("compare: A/B compares remixes of light-group layers: start the editor with --light-mix"),
               QJSValue();
    // The scene the viewport renders: the latest frame's, or (before one) the open scene as the
    // render thread renders it (every light unmuted, render_worker.h).
    const scene::Scene rendered =
        frame.layersScene ? *frame.layersScene : render::remixBaseScene(*document->scene());
    view->start(sides[0], sides[1], rendered, compareRenderContext(*renderer, document->path()));
    if (frame.image)
        if (auto shown = view->showFrame(frame); !shown) {
            view->stop();
            fail(QString::fromStdString(shown.error().message()));
            return {};
        }
    QJSValue modes = m_engine->newObject();
    modes.setProperty("a", compareModeName(view->modes()[0]));
    modes.setProperty("b", compareModeName(view->modes()[1]));
    return modes;
}

QJSValue AppApi::compareSamples() {
    LightMixCompare* view = m_window->lightMixCompare();
    if (!view->active()) return fail("compareSamples: no A/B compare is showing"), QJSValue();
    QJSValue samples = m_engine->newArray(2);
    samples.setProperty(0, view->sideSamples(0));
    samples.setProperty(1, view->sideSamples(1));
    return samples;
}

bool AppApi::setCompareWipe(double fraction) {
    if (!m_window->lightMixCompare()->active()) return fail("setCompareWipe: no A/B compare is showing");
    m_window->lightMixCompare()->setWipe(fraction);
    return true;
}

QJSValue AppApi::compareMeans() {
    LightMixCompare* view = m_window->lightMixCompare();
    if (!view->active() || view->composite().isNull()) {
        fail("compareMeans: no A/B compare frame yet");
        return {};
    }
    QJSValue means = m_engine->newArray(2);
    means.setProperty(0, view->sideMeans()[0]);
    means.setProperty(1, view->sideMeans()[1]);
    return means;
}

bool AppApi::saveCompare(const QString& path) {
    const QImage shown = m_window->lightMixCompare()->composite();
    if (shown.isNull()) return fail("saveCompare: no A/B compare frame yet");
    return shown.save(path, "PNG") ? true : fail("saveCompare: cannot write " + path);
}

bool AppApi::endCompare() {
    m_window->lightMixCompare()->stop();
    return true;
}

} // namespace wavelit::editor
