// LightMixPanel (docs/lightmix.md): one row per analytic light — a mute box, the light's name and
// LightMix group, an intensity slider (logarithmic; one drag is one undo step) and box, and a
// colour swatch that opens a colour dialog — and one for the environment's intensity. Each
// change is an ordinary property edit (editRequested, like the property panel's), so it is
// undoable and saved; with `wavelit --light-mix` the render thread shows it by a remix.
// Widgets are named for tests and scripts: "mute:<light>", "intensity:<light>",
// "intensity:environment", "slider:<light>", "slider:environment", "swatch:<light>".
#pragma once

#include "commands/property_edit.h"

#include "scene/scene.h"

#include <QWidget>

#include <vector>

class QGridLayout;

namespace wavelit::editor {

class GestureTracker;

class LightMixPanel : public QWidget {
    Q_OBJECT
public:
    explicit LightMixPanel(QWidget* parent = nullptr);
    // Shows the scene's lights: rows are rebuilt when the lights changed (added, removed,
    // renamed), otherwise their values are updated without emitting edits.
    void setScene(const scene::Scene& scene);

signals:
    void editRequested(const wavelit::editor::PropertyEdit& edit);

private:
    void rebuild(const scene::Scene& scene);
    void update(const scene::Scene& scene);

    QGridLayout* m_grid;
    GestureTracker* m_gestures; // a slider drag is one gesture
    std::vector<std::pair<scene::EntityId, std::string>> m_rows; // the lights shown, in order
};

} // namespace wavelit::editor
