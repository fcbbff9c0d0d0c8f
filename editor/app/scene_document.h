// SceneDocument: the open scene and its files. Holds an immutable snapshot
// (shared_ptr<const Scene>) that the panels read and the render thread copies; every edit makes
// a new snapshot. Loading and saving run on a pool thread (the UI thread never waits on disk);
// results come back as signals, errors with a message that names the file.
//
// The document is the scene file plus, when the scene refers to a lighting setup (*.wllight),
// that setup: editing its lights or environment marks the document modified like any other edit.
// Save writes the scene and, if its lighting was edited, the setup it refers to; Save As lets the
// caller choose where edited referenced lighting goes (app/save_plan.h), a copy beside the new
// scene by default. Each file is written atomically (temp, fsync, rename), the setup first: a
// failure leaves the scene file untouched and is reported.
//
// Undo: one step per user edit (edits of one gesture merge, commands/property_command.h), at most
// kUndoLimit steps, oldest dropped first (each step holds two property values, ~100 bytes).
#pragma once

#include "app/save_plan.h"
#include "commands/lighting_command.h"
#include "commands/property_edit.h"
#include "scene/change_set.h"

#include <QFutureWatcher>
#include <QUndoStack>
#include <QObject>
#include <QString>

#include <memory>
#include <optional>

namespace wavelit::editor {

class SceneDocument : public QObject {
    Q_OBJECT
public:
    static constexpr int kUndoLimit = 1000;

    explicit SceneDocument(QObject* parent = nullptr);
    ~SceneDocument() override;

    std::shared_ptr<const scene::Scene> scene() const { return m_scene; }
    QString path() const { return m_path; }
    bool isLoading() const { return m_loading != nullptr; }
    bool isSaving() const { return m_saving != nullptr; }
    // Unsaved edits (of the scene or of the lighting setup it refers to).
    bool isModified() const;
    // The referenced lighting setup differs from its file (false for inline lighting).
    bool lightingEdited() const;
    // Save As's default: Copy for edited referenced lighting, else keep the reference.
    LightingSave defaultLightingSave() const;

    // Asynchronous. A newer open() supersedes one still loading.
    void open(const QString& path);
    // Save: the scene to path() and, if edited, its referenced setup to its own file.
    void save();
    // Save As: the scene to `path`; referenced lighting as `choice` (default: defaultLightingSave()).
    void saveAs(const QString& path, std::optional<LightingSave> choice = std::nullopt);
    // Replaces the document synchronously (tests, scripts that build scenes).
    void setScene(std::shared_ptr<const scene::Scene> scene, const QString& path);
    // Replaces the document with a recovered state (app/recovery_store.h): modified until saved;
    // `savedLighting` is the referenced setup as its file holds it.
    void restoreRecovered(std::shared_ptr<const scene::Scene> scene, const QString& path,
                          scene::LightingSetup savedLighting);

    // Checks one edit against the registry and, if valid, pushes it onto the undo stack (which
    // applies it). Opening a scene clears the stack.
    util::Status apply(const PropertyEdit& edit);
    // LightMix solo (docs/lightmix.md): mutes every other light and unmutes `light`, as one undo
    // step (the environment is left as it is). Error: no scene, or not a light of it.
    util::Status solo(scene::EntityId light);
    // Outline edits (issue 14, app/outline_edits.h): entities added, removed or duplicated, as ONE
    // undo step named `text`. Error: no scene, or the set does not apply to it (nothing changes).
    util::Status applyChanges(const scene::ChangeSet& changes, const QString& text);
    // Lighting setups (issue 14): replaces the scene's lighting — environment, lights and where
    // the setup lives — as one undo step. Lights and the map reach the renderer as one change set.
    util::Status applyLighting(LightingState after, const QString& text);
    // The lighting as the document holds it (setup, file it refers to, that file's contents).
    LightingState lightingState() const;
    // File -> New: an empty scene without a file (a constant white environment, default camera).
    void newScene();
    QUndoStack* undoStack() const { return m_undo; }
    // The camera's display exposure in EV: a Display edit (never restarts the render).
    util::Status setExposure(float ev);

signals:
    void sceneOpened(std::shared_ptr<const wavelit::scene::Scene> scene, const QString& path);
    void openFailed(const QString& message);
    // The scene opened, but the loader repaired problems on the way (each line names one).
    void openRepaired(const QString& message);
    // A Restart/Rebuild edit (or its undo): the render thread needs the new scene; `changes`
    // leads from the previous scene to it (RenderController::renderEdit updates only that).
    void sceneEdited(std::shared_ptr<const wavelit::scene::Scene> scene,
                     const wavelit::scene::ChangeSet& changes);
    // A Display edit: re-tone-map only.
    void displayChanged(std::shared_ptr<const wavelit::scene::Scene> scene);
    void saved(const QString& path);
    void saveFailed(const QString& message);
    void editFailed(const QString& message);
    void modifiedChanged(bool modified);

private:
    struct LoadResult;
    void onLoaded();
    void onSaved();
    void commit(const PropertyEdit& edit); // applies without undo bookkeeping (commands call it)
    void commitChanges(const scene::ChangeSet& changes); // SceneEditCommand's callback
    void commitLighting(const LightingState& state);      // LightingCommand's callback
    void startSave(SavePlan plan);

    std::shared_ptr<const scene::Scene> m_scene;
    QString m_path;
    // The referenced setup as its file holds it (what lightingEdited() compares with).
    scene::LightingSetup m_savedLighting;
    QUndoStack* m_undo;
    QFutureWatcher<std::shared_ptr<LoadResult>>* m_loading = nullptr;
    QFutureWatcher<QString>* m_saving = nullptr; // empty string = success
    std::optional<SavePlan> m_savingPlan;
    int m_savingUndoIndex = 0; // the undo index the saved snapshot corresponds to
    bool m_recovered = false;  // restored from a recovery file and not saved since
};

} // namespace wavelit::editor
