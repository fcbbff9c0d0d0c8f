// SceneDocument: the open scene and its file. Holds an immutable snapshot
// (shared_ptr<const Scene>) that the panels read and the render thread copies; every edit makes
// a new snapshot. Loading and saving run on a pool thread (the UI thread never waits on disk);
// results come back as signals, errors with a message that names the file.
#pragma once

#include "commands/property_edit.h"

#include <QFutureWatcher>
#include <QUndoStack>
#include <QObject>
#include <QString>

#include <memory>

namespace wavelit::editor {

class SceneDocument : public QObject {
    Q_OBJECT
public:
    explicit SceneDocument(QObject* parent = nullptr);
    ~SceneDocument() override;

    std::shared_ptr<const scene::Scene> scene() const { return m_scene; }
    QString path() const { return m_path; }
    bool isLoading() const { return m_loading != nullptr; }
    bool isSaving() const { return m_saving != nullptr; }

    // Asynchronous. A newer open() supersedes one still loading.
    void open(const QString& path);
    void saveAs(const QString& path);
    // Replaces the document synchronously (tests, scripts that build scenes).
    void setScene(std::shared_ptr<const scene::Scene> scene, const QString& path);

    // Checks one edit against the registry and, if valid, pushes it onto the undo stack (which
    // applies it). Opening a scene clears the stack.
    util::Status apply(const PropertyEdit& edit);
    QUndoStack* undoStack() const { return m_undo; }
    // The camera's display exposure in EV: a Display edit (never restarts the render).
    util::Status setExposure(float ev);

signals:
    void sceneOpened(std::shared_ptr<const wavelit::scene::Scene> scene, const QString& path);
    void openFailed(const QString& message);
    // A Restart/Rebuild edit: the render thread needs the new scene.
    void sceneEdited(std::shared_ptr<const wavelit::scene::Scene> scene);
    // A Display edit: re-tone-map only.
    void displayChanged(std::shared_ptr<const wavelit::scene::Scene> scene);
    void saved(const QString& path);
    void saveFailed(const QString& message);
    void editFailed(const QString& message);

private:
    struct LoadResult;
    void onLoaded();
    void onSaved();
    void commit(const PropertyEdit& edit); // applies without undo bookkeeping (commands call it)

    std::shared_ptr<const scene::Scene> m_scene;
    QString m_path;
    QUndoStack* m_undo;
    QFutureWatcher<std::shared_ptr<LoadResult>>* m_loading = nullptr;
    QFutureWatcher<QString>* m_saving = nullptr; // empty string = success
    QString m_savingPath;
    std::shared_ptr<const scene::Scene> m_savingScene; // with paths relative to m_savingPath
};

} // namespace wavelit::editor
