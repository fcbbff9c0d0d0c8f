// RecoveryStore: where the editor keeps the unsaved state of open documents so a crash loses no
// work (autosave, app/autosave_controller.h). One recovery per scene file, in a folder of its own
// (WAVELIT_RECOVERY_DIR, else the user's local application data folder + "/recovery"):
//   <key>.wlscene  the whole document as a self-contained scene: lighting inline, every path
//                  re-expressed relative to the recovery folder;
//   <key>.json     {"scene": original scene file, "lighting": the *.wllight it referred to (or
//                  ""), "saved": ISO time}.
// <key> is a hash of the scene file's absolute path ("untitled" for a document without one).
// Writes are atomic (scene_io); reading back restores the original references.
#pragma once

#include "scene/scene.h"
#include "util/result.h"

#include <QDateTime>
#include <QString>

#include <memory>
#include <optional>

namespace wavelit::editor {

struct Recovery {
    QString recoveryFile; // the <key>.wlscene
    QString scenePath;    // the document it recovers
    QDateTime saved;
};

struct RecoveredDocument {
    std::shared_ptr<const scene::Scene> scene; // paths relative to the original scene file again
    scene::LightingSetup savedLighting;        // the referenced setup as its file holds it now
};

class RecoveryStore {
public:
    explicit RecoveryStore(QString folder = defaultFolder());
    static QString defaultFolder();

    QString folder() const { return m_folder; }
    QString recoveryFileFor(const QString& scenePath) const;

    // Writes the document's state (blocking: call it off the UI thread).
    util::Status write(const scene::Scene& scene, const QString& scenePath) const;
    // The recovery of this scene file, if there is one newer than the file itself.
    std::optional<Recovery> find(const QString& scenePath) const;
    // Loads a recovery back (blocking: meshes and maps load too).
    util::Result<RecoveredDocument> read(const Recovery& recovery) const;
    void remove(const QString& scenePath) const;

private:
    QString m_folder;
};

} // namespace wavelit::editor
