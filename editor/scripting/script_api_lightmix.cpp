// AppApi's LightMix calls (docs/scripting.md, docs/lightmix.md): mute and solo as ordinary,
// undoable edits of the lights' `muted` property, and the latest frame's update status.
#include "scripting/script_api.h"

#include "app/main_window.h"
#include "app/scene_document.h"
#include "panels/entity_ref.h"
#include "viewport/render_controller.h"


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

} // namespace wavelit::editor
