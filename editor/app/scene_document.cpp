#include "app/scene_document.h"

#include "commands/property_command.h"
#include "commands/scene_edit_command.h"
#include "panels/entity_ref.h"

#include "scene/scene_compare.h"
#include "scene/scene_io.h"

#include <QDir>
#include <QtConcurrent/QtConcurrentRun>

namespace wavelit::editor {

struct SceneDocument::LoadResult {
    QString path;
    std::shared_ptr<const scene::Scene> scene; // null on failure
    QString error;
    QStringList repairs; // the loader's warnings
};

namespace {

// The message always names the file, whatever the loader's own wording.
QString describeFailure(const QString& action, const QString& path, const util::Error& error) {
    return QStringLiteral("Could not %1 '%2':\n%3")
        .arg(action, QDir::toNativeSeparators(path), QString::fromStdString(error.message()));
}

// "sun intensity", "camera position": the Edit menu's "Undo ..." text.
QString stepName(const scene::Scene& scene, const PropertyEdit& edit) {
    const scene::PropertyInfo* info = scene::findProperty(edit.entity.kind, edit.name);
    std::string entity = entityName(scene, edit.entity);
    if (entity == "Camera" || entity == "Environment" || entity == "Render")
        entity = scene::entityKindName(edit.entity.kind);
    return QStringLiteral("%1 %2").arg(QString::fromStdString(entity),
                                       QString::fromStdString(info ? info->label : edit.name).toLower());
}

} // namespace

SceneDocument::SceneDocument(QObject* parent) : QObject(parent), m_undo(new QUndoStack(this)) {
    m_undo->setUndoLimit(kUndoLimit);
    connect(m_undo, &QUndoStack::cleanChanged, this, [this] { emit modifiedChanged(isModified()); });
}

SceneDocument::~SceneDocument() = default;

bool SceneDocument::isModified() const { return m_scene && (m_recovered || !m_undo->isClean()); }

bool SceneDocument::lightingEdited() const {
    return m_scene && !m_scene->lightingPath.empty() &&
           !scene::firstDifference(m_scene->lighting, m_savedLighting).empty();
}

LightingSave SceneDocument::defaultLightingSave() const {
    return lightingEdited() ? LightingSave::Copy : LightingSave::Reference;
}

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
        scene::LoadReport report;
        auto loaded = scene::loadScene(path.toStdString(), &report);
        if (loaded)
            result->scene = std::make_shared<const scene::Scene>(std::move(loaded.value()));
        else
            result->error = describeFailure("open scene", path, loaded.error());
        for (const auto& warning : report.warnings) result->repairs << QString::fromStdString(warning);
        return result;
    }));
}

void SceneDocument::onLoaded() {
    auto* watcher = m_loading;
    m_loading = nullptr;
    watcher->deleteLater();
    std::shared_ptr<LoadResult> result = watcher->result();
    if (!result->scene) {
        emit openFailed(result->error); // the open document stays as it is
        return;
    }
    setScene(result->scene, result->path);
    if (!result->repairs.isEmpty())
        emit openRepaired(QStringLiteral("'%1' opened with repairs:\n%2")
                              .arg(QDir::toNativeSeparators(result->path), result->repairs.join('\n')));
}

void SceneDocument::restoreRecovered(std::shared_ptr<const scene::Scene> scene, const QString& path,
                                     scene::LightingSetup savedLighting) {
    setScene(std::move(scene), path);
    m_savedLighting = std::move(savedLighting);
    m_recovered = true;
    emit modifiedChanged(true);
}

void SceneDocument::setScene(std::shared_ptr<const scene::Scene> scene, const QString& path) {
    m_recovered = false;
    m_undo->clear();
    m_scene = std::move(scene);
    m_savedLighting = m_scene ? m_scene->lighting : scene::LightingSetup{};
    m_path = path;
    emit sceneOpened(m_scene, m_path);
    emit modifiedChanged(isModified());
}

void SceneDocument::save() {
    if (m_path.isEmpty()) {
        emit saveFailed(tr("The scene has no file yet: use Save As."));
        return;
    }
    saveAs(m_path, lightingEdited() ? LightingSave::SaveSetup : LightingSave::Reference);
}

void SceneDocument::saveAs(const QString& path, std::optional<LightingSave> choice) {
    if (!m_scene || m_saving) {
        emit saveFailed(m_scene ? tr("A save is already in progress.") : tr("No scene to save."));
        return;
    }
    auto plan = planSave(*m_scene, m_path.toStdString(), path.toStdString(),
                         choice.value_or(defaultLightingSave()), lightingEdited());
    if (!plan) {
        emit saveFailed(describeFailure("save scene to", path, plan.error()));
        return;
    }
    startSave(std::move(plan.value()));
}

void SceneDocument::startSave(SavePlan plan) {
    m_savingPlan = plan;
    m_savingUndoIndex = m_undo->index();
    m_saving = new QFutureWatcher<QString>(this);
    connect(m_saving, &QFutureWatcherBase::finished, this, &SceneDocument::onSaved);
    m_saving->setFuture(QtConcurrent::run([plan = std::move(plan)] {
        // The setup first: if it fails, the scene file still refers to the intact old setup.
        if (plan.lighting) {
            auto status = scene::saveLightingSetup(*plan.lighting, plan.lightingFile);
            if (!status)
                return describeFailure("save lighting setup to", QString::fromStdString(plan.lightingFile),
                                       status.error());
        }
        auto status = scene::saveScene(*plan.scene, plan.scenePath);
        return status ? QString()
                      : describeFailure("save scene to", QString::fromStdString(plan.scenePath), status.error());
    }));
}

void SceneDocument::onSaved() {
    auto* watcher = m_saving;
    m_saving = nullptr;
    watcher->deleteLater();
    const SavePlan plan = std::move(*m_savingPlan);
    m_savingPlan.reset();
    const QString error = watcher->result();
    if (!error.isEmpty()) {
        emit saveFailed(error);
        return;
    }
    // The document now lives at the new path; its paths are relative to it. Edits made while the
    // save ran are kept (only the path fields of the saved snapshot are taken over).
    auto current = std::make_shared<scene::Scene>(*m_scene);
    current->lightingPath = plan.scene->lightingPath;
    current->lighting.environment.path = plan.scene->lighting.environment.path;
    for (size_t i = 0; i < current->objects.size() && i < plan.scene->objects.size(); ++i)
        if (current->objects[i].id == plan.scene->objects[i].id)
            current->objects[i].meshPath = plan.scene->objects[i].meshPath;
    m_scene = std::move(current);
    if (plan.lighting) m_savedLighting = *plan.lighting;
    else if (m_scene->lightingPath.empty()) m_savedLighting = m_scene->lighting;
    m_path = QString::fromStdString(plan.scenePath);
    if (m_undo->index() == m_savingUndoIndex) {
        m_recovered = false;
        m_undo->setClean();
    }
    emit saved(m_path);
    emit modifiedChanged(isModified());
}

util::Status SceneDocument::solo(scene::EntityId light) {
    if (!m_scene || !m_scene->findLight(light))
        return util::makeError(util::ErrorKind::Invalid, "", "solo: no such light");
    const std::shared_ptr<const scene::Scene> before = m_scene; // apply() replaces m_scene
    m_undo->beginMacro(tr("solo %1").arg(QString::fromStdString(before->findLight(light)->name)));
    util::Status status = util::okStatus();
    for (const scene::Light& l : before->lighting.lights)
        if (l.muted != (l.id != light) && status)
            status = apply({{EntityKind::Light, l.id}, "muted", l.id != light});
    m_undo->endMacro();
    return status;
}

util::Status SceneDocument::apply(const PropertyEdit& edit) {
    if (!m_scene) return util::makeError(util::ErrorKind::Invalid, "", "no scene is open");
    auto applied = applyEdit(*m_scene, edit);
    if (!applied) return applied.error();
    m_undo->push(new PropertyCommand(edit, applied->previous,
                                     [this](const PropertyEdit& e) { commit(e); },
                                     stepName(*m_scene, edit)));
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
        emit sceneEdited(m_scene, applied->changes);
}

util::Status SceneDocument::applyChanges(const scene::ChangeSet& changes, const QString& text) {
    if (!m_scene) return util::makeError(util::ErrorKind::Invalid, "", "no scene is open");
    scene::Scene check = *m_scene; // refuse a set that does not apply before it reaches the stack
    if (auto status = changes.apply(check); !status) return status;
    m_undo->push(new SceneEditCommand(changes, [this](const scene::ChangeSet& c) { commitChanges(c); }, text));
    return util::okStatus();
}

void SceneDocument::commitChanges(const scene::ChangeSet& changes) {
    auto edited = std::make_shared<scene::Scene>(*m_scene);
    if (auto status = changes.apply(*edited); !status) {
        emit editFailed(QString::fromStdString(status.error().message()));
        return;
    }
    m_scene = std::move(edited);
    emit sceneEdited(m_scene, changes);
}

LightingState SceneDocument::lightingState() const {
    if (!m_scene) return {};
    return {m_scene->lighting, m_scene->lightingPath, m_savedLighting};
}

util::Status SceneDocument::applyLighting(LightingState after, const QString& text) {
    if (!m_scene) return util::makeError(util::ErrorKind::Invalid, "", "no scene is open");
    m_undo->push(new LightingCommand(lightingState(), std::move(after),
                                     [this](const LightingState& s) { commitLighting(s); }, text));
    return util::okStatus();
}

void SceneDocument::commitLighting(const LightingState& state) {
    // The render thread gets every light removed and the new ones added, and every environment
    // property (the map among them: its texels are new even when the file name is not).
    scene::ChangeSet changes;
    for (const scene::Light& light : m_scene->lighting.lights)
        (void)changes.removeEntity(*m_scene, {EntityKind::Light, light.id});
    auto edited = std::make_shared<scene::Scene>(*m_scene);
    edited->lighting = state.lighting;
    edited->lightingPath = state.lightingPath;
    for (size_t i = 0; i < state.lighting.lights.size(); ++i)
        changes.add(scene::EntityEdit{true, i, state.lighting.lights[i]});
    const EntityRef environment{EntityKind::Environment, scene::kInvalidId};
    for (const scene::PropertyInfo& info : scene::properties(EntityKind::Environment))
        changes.add(scene::PropertyEdit{environment, info.name, info.get(&m_scene->lighting.environment),
                                        info.get(&edited->lighting.environment)});
    m_scene = std::move(edited);
    m_savedLighting = state.savedLighting;
    emit sceneEdited(m_scene, changes);
}

void SceneDocument::newScene() {
    auto empty = std::make_shared<scene::Scene>();
    empty->name = "untitled";
    setScene(std::move(empty), QString());
}

util::Status SceneDocument::setExposure(float ev) {
    return apply({EntityRef{EntityKind::Camera, scene::kInvalidId}, "exposure", ev});
}

} // namespace wavelit::editor
