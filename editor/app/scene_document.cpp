#include "app/scene_document.h"

#include "commands/property_command.h"

#include "scene/scene_io.h"

#include <QDir>
#include <QFileInfo>
#include <QtConcurrent/QtConcurrentRun>

namespace wavelit::editor {

struct SceneDocument::LoadResult {
    QString path;
    std::shared_ptr<const scene::Scene> scene; // null on failure
    QString error;
};

namespace {

// The message always names the file, whatever the loader's own wording.
QString describeFailure(const QString& action, const QString& path, const util::Error& error) {
    return QStringLiteral("Could not %1 '%2':\n%3")
        .arg(action, QDir::toNativeSeparators(path), QString::fromStdString(error.message()));
}

// A relative path written in a file at `fromDir`, re-expressed for a file at `toDir`.
std::string rebasePath(const std::string& path, const QDir& fromDir, const QDir& toDir) {
    if (path.empty() || QDir::isAbsolutePath(QString::fromStdString(path))) return path;
    const QString absolute = QDir::cleanPath(fromDir.absoluteFilePath(QString::fromStdString(path)));
    return toDir.relativeFilePath(absolute).toStdString();
}

// Paths in a scene are relative to its file (DESIGN.md §6), and saveScene writes them as they are:
// saving into another folder must re-express them for the new file. An environment inside a
// separate *.wllight stays relative to that file, which does not move.
std::shared_ptr<const scene::Scene> rebasedForSave(const scene::Scene& scene, const QString& from,
                                                   const QString& to) {
    const QDir fromDir = QFileInfo(from).absoluteDir();
    const QDir toDir = QFileInfo(to).absoluteDir();
    auto out = std::make_shared<scene::Scene>(scene);
    if (from.isEmpty() || fromDir == toDir) return out;
    for (auto& object : out->objects) object.meshPath = rebasePath(object.meshPath, fromDir, toDir);
    if (out->lightingPath.empty())
        out->lighting.environment.path = rebasePath(out->lighting.environment.path, fromDir, toDir);
    else
        out->lightingPath = rebasePath(out->lightingPath, fromDir, toDir);
    return out;
}

} // namespace

SceneDocument::SceneDocument(QObject* parent) : QObject(parent), m_undo(new QUndoStack(this)) {}

SceneDocument::~SceneDocument() = default;

void SceneDocument::open(const QString& path) {
    if (m_loading) {
        m_loading->disconnect(this);
        m_loading->deleteLater(); // its thread finishes on its own; the result is dropped
    }
    m_loading = new QFutureWatcher<std::shared_ptr<LoadResult>>(this);
    connect(m_loading, &QFutureWatcherBase::finished, this, &SceneDocument::onLoaded);
    m_loading->setFuture(QtConcurrent::run([path] {
        auto result = std::make_shared<LoadResult>();
        result->path = path;
        auto loaded = scene::loadScene(path.toStdString());
        if (loaded)
            result->scene = std::make_shared<const scene::Scene>(std::move(loaded.value()));
        else
            result->error = describeFailure("open scene", path, loaded.error());
        return result;
    }));
}

void SceneDocument::onLoaded() {
    auto* watcher = m_loading;
    m_loading = nullptr;
    watcher->deleteLater();
    std::shared_ptr<LoadResult> result = watcher->result();
    if (!result->scene) {
        emit openFailed(result->error);
        return;
    }
    setScene(result->scene, result->path);
}

void SceneDocument::setScene(std::shared_ptr<const scene::Scene> scene, const QString& path) {
    m_undo->clear();
    m_scene = std::move(scene);
    m_path = path;
    emit sceneOpened(m_scene, m_path);
}

void SceneDocument::saveAs(const QString& path) {
    if (!m_scene || m_saving) {
        emit saveFailed(m_scene ? tr("A save is already in progress.") : tr("No scene to save."));
        return;
    }
    m_savingPath = path;
    m_savingScene = rebasedForSave(*m_scene, m_path, path);
    m_saving = new QFutureWatcher<QString>(this);
    connect(m_saving, &QFutureWatcherBase::finished, this, &SceneDocument::onSaved);
    m_saving->setFuture(QtConcurrent::run([path, scene = m_savingScene] {
        auto status = scene::saveScene(*scene, path.toStdString());
        return status ? QString() : describeFailure("save scene to", path, status.error());
    }));
}

void SceneDocument::onSaved() {
    auto* watcher = m_saving;
    m_saving = nullptr;
    watcher->deleteLater();
    const QString error = watcher->result();
    if (!error.isEmpty()) {
        m_savingScene.reset();
        emit saveFailed(error);
        return;
    }
    // The document now lives at the new path; its paths are relative to it. Edits made while the
    // save ran are kept (only the path fields of the saved snapshot are taken over).
    if (m_scene != m_savingScene) {
        auto current = std::make_shared<scene::Scene>(*m_scene);
        current->lightingPath = m_savingScene->lightingPath;
        if (current->lightingPath.empty())
            current->lighting.environment.path = m_savingScene->lighting.environment.path;
        for (size_t i = 0; i < current->objects.size() && i < m_savingScene->objects.size(); ++i)
            if (current->objects[i].id == m_savingScene->objects[i].id)
                current->objects[i].meshPath = m_savingScene->objects[i].meshPath;
        m_scene = std::move(current);
    }
    m_savingScene.reset();
    m_path = m_savingPath;
    emit saved(m_path);
}

util::Status SceneDocument::apply(const PropertyEdit& edit) {
    if (!m_scene) return util::makeError(util::ErrorKind::Invalid, "", "no scene is open");
    auto applied = applyEdit(*m_scene, edit);
    if (!applied) return applied.error();
    m_undo->push(new PropertyCommand(edit, applied->previous,
                                     [this](const PropertyEdit& e) { commit(e); }));
    return util::okStatus();
}

void SceneDocument::commit(const PropertyEdit& edit) {
    // Undo/redo replay values that were valid when first applied; a failure here would mean the
    // scene changed under the stack, which setScene() prevents by clearing it.
    auto applied = applyEdit(*m_scene, edit);
    if (!applied) {
        emit editFailed(QString::fromStdString(applied.error().message()));
        return;
    }
    m_scene = applied->scene;
    if (applied->change == scene::ChangeKind::Display)
        emit displayChanged(m_scene);
    else
        emit sceneEdited(m_scene);
}

util::Status SceneDocument::setExposure(float ev) {
    return apply({EntityRef{EntityKind::Camera, scene::kInvalidId}, "exposure", ev});
}

} // namespace wavelit::editor
