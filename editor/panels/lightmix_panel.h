// LightMixPanel (docs/lightmix.md): one row per LightMix GROUP, the layers the render keeps —
// lights that share a `group` property are one row named by the group, a light without one is a
// row of its own (named after it), then `environment`, then `emission` when some material emits
// (lightMixRows). Each row has a mute box, a solo button, the group's name, an intensity slider
// (logarithmic; one drag is one undo step) and box, and a colour swatch that opens a colour
// dialog. A row's intensity is its first lit member's; changing it scales every member's
// intensity (a light's, the environment's, a material's emission) by the same factor, and a
// colour pick multiplies every member's colour by the same per-channel factor, so a group stays
// one layer times one weight and the render remixes instead of restarting.
//
// Edits: a change of one property of one entity is an ordinary property edit (editRequested,
// like the property panel's: a slider drag merges into one undo step by its gesture); a change
// of several (a group of lights, solo) is ONE change set (groupEditRequested), and the edits of
// one slider drag share a gesture that groupGestureEnded closes (the receiver makes the drag one
// undo step: lightmix/group_edit_sink.h).
// Mute: lights have a `muted` property; the environment and emission have none, so muting them
// sets their intensity / emission to 0 and unmuting restores the value the panel saw before
// (1 / nothing when it never saw one). Solo silences every other row, the environment and
// emission included (the outline's Alt-click solo is about lights only).
// Widgets are named for tests and scripts: "mute:<row>", "solo:<row>", "slider:<row>",
// "intensity:<row>", "swatch:<row>", "label:<row>".
#pragma once

#include "commands/property_edit.h"

#include "scene/change_set.h"
#include "scene/scene.h"

#include <QMetaType>
#include <QWidget>

#include <map>
#include <optional>
#include <string>
#include <vector>

class QGridLayout;

namespace wavelit::editor {

class GestureTracker;

struct LightMixRow {
    enum class Kind { Lights, Environment, Emission };
    Kind kind = Kind::Lights;
    std::string name;                      // the group's layer name
    std::vector<scene::EntityId> lights;   // member lights, in scene order
    std::vector<scene::EntityId> materials; // Emission: the emissive materials
};

// The rows for a scene, in the render's layer order (render::lightGroupsOf): light groups by
// first appearance, `environment`, then `emission` when a material emits. A light whose group is
// `environment` or `emission` joins that row.
std::vector<LightMixRow> lightMixRows(const scene::Scene& scene);

class LightMixPanel : public QWidget {
    Q_OBJECT
public:
    explicit LightMixPanel(QWidget* parent = nullptr);
    // Shows the scene's groups: rows are rebuilt when the groups changed (lights added, removed,
    // renamed or regrouped), otherwise their values are updated without emitting edits.
    void setScene(const scene::Scene& scene);
    const std::vector<LightMixRow>& rows() const { return m_rows; }

signals:
    void editRequested(const wavelit::editor::PropertyEdit& edit);
    // Several properties as one change set against the scene last shown; `text` names the undo
    // step; `gesture` is a slider drag's (kNoGesture: a step of its own).
    void groupEditRequested(const wavelit::scene::ChangeSet& changes, const QString& text,
                            wavelit::editor::GestureId gesture);
    void groupGestureEnded();

private:
    struct Target {
        EntityRef entity;
        std::string property;
        scene::PropertyValue value;
    };
    void rebuild();
    void refresh();
    void emitTargets(const std::vector<Target>& targets, const QString& text, GestureId gesture);
    // The row's intensity as shown (its first lit member's) and colour.
    double rowIntensity(const LightMixRow& row) const;
    glm::vec3 rowColour(const LightMixRow& row) const;
    bool rowMuted(const LightMixRow& row) const;
    std::vector<Target> scaled(const LightMixRow& row, double intensity) const;
    std::vector<Target> tinted(const LightMixRow& row, const glm::vec3& colour) const;
    std::vector<Target> muted(const LightMixRow& row, bool on);
    void solo(const LightMixRow& row);

    QGridLayout* m_grid;
    GestureTracker* m_gestures; // a slider drag is one gesture
    scene::Scene m_scene;       // the scene last shown (change sets start from it)
    std::vector<LightMixRow> m_rows;
    std::optional<float> m_environmentBeforeMute;
    std::map<scene::EntityId, glm::vec3> m_emissionBeforeMute;
};

} // namespace wavelit::editor

Q_DECLARE_METATYPE(wavelit::scene::ChangeSet)
