#include "app/file_actions.h"

#include "app/background_task.h"
#include "app/editor_actions.h"
#include "app/error_reporter.h"
#include "app/main_window.h"
#include "app/outline_edits.h"
#include "app/recent_files.h"
#include "app/save_file_dialog.h"
#include "app/scene_document.h"
#include "app/unsaved_changes_prompt.h"
#include "panels/outline_panel.h"
#include "panels/property_panel.h"
#include "viewport/render_controller.h"
#include "viewport/viewport_widget.h"

#include "scene/image_io.h"
#include "scene/mesh_loader.h"
#include "scene/scene_io.h"

#include <QAction>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMimeData>
#include <QProgressDialog>
#include <QStatusBar>

namespace wavelit::editor {
namespace {

const QStringList kDroppable{"wlscene", "wllight", "exr", "hdr", "obj"};

QString folderOf(const QString& file) { return QFileInfo(file).absolutePath(); }

// The folder the environment map path of `scene`'s lighting is relative to: the *.wllight it
// refers to, or the scene file (scene_io.h).
QString environmentBase(const scene::Scene& scene, const QString& scenePath) {
    const QString sceneFolder = folderOf(scenePath);
    if (scene.lightingPath.empty()) return sceneFolder;
    return folderOf(QDir(sceneFolder).filePath(QString::fromStdString(scene.lightingPath)));
}

QString message(const util::Error& error) { return QString::fromStdString(error.message()); }

// The file is named in every message, whatever the layer below said.
QString naming(const QString& path, const QString& problem) {
    const QString native = QDir::toNativeSeparators(path);
    return problem.contains(native) || problem.contains(path) ? problem
                                                                : QStringLiteral("'%1': %2").arg(native, problem);
}

} // namespace

FileActions::FileActions(MainWindow* window)
    : QObject(window), m_window(window), m_recent(new RecentFiles(this)), m_render(new RenderToFile(this)) {
    setObjectName("fileActions");
    EditorActions* actions = window->actions();
    QMenu* file = actions->fileMenu();
    QAction* open = actions->action("actionOpenScene");
    QAction* quit = actions->action("actionQuit");
    auto make = [&](const QString& name, const QString& text, const QKeySequence& key = {}) {
        auto* a = new QAction(text, window);
        a->setObjectName(name);
        a->setShortcut(key);
        window->addAction(a);
        return a;
    };
    QAction* newScene = make("actionNewScene", tr("&New scene"), QKeySequence::New);
    file->insertAction(open, newScene);
    m_recentMenu = new QMenu(tr("Open &recent"), window);
    m_recentMenu->setObjectName("menuRecent");
    file->insertMenu(actions->action("actionSaveScene"), m_recentMenu);
    file->insertSeparator(quit);
    QAction* applyLighting = make("actionApplyLighting", tr("Apply &lighting setup…"));
    QAction* saveLighting = make("actionSaveLighting", tr("Save lighting setup &as…"));
    QAction* renderFile = make("actionRenderToFile", tr("Render to &file…"), QKeySequence(Qt::CTRL | Qt::Key_R));
    file->insertAction(quit, applyLighting);
    file->insertAction(quit, saveLighting);
    file->insertSeparator(quit);
    file->insertAction(quit, renderFile);
    file->insertSeparator(quit);
    rebuildRecentMenu();

    connect(newScene, &QAction::triggered, this, [this] {
        m_window->actions()->prompt()->ask(tr("start a new scene"), [this] { this->newScene(); });
    });
    connect(applyLighting, &QAction::triggered, this, [this] {
        const QString path = QFileDialog::getOpenFileName(m_window, tr("Apply lighting setup"),
                                                          folderOf(m_window->document()->path()),
                                                          tr("Lighting setups (*.wllight)"));
        if (!path.isEmpty()) this->applyLighting(path, [](const QString&) {});
    });
    connect(saveLighting, &QAction::triggered, this, [this] {
        const QString path = askSavePath(m_window, SaveTarget::Lighting, folderOf(m_window->document()->path()));
        if (!path.isEmpty()) this->saveLighting(path, [](const QString&) {});
    });
    connect(renderFile, &QAction::triggered, this, [this] {
        const QString path = askSavePath(m_window, SaveTarget::Render, folderOf(m_window->document()->path()));
        if (path.isEmpty()) return;
        bool ok = false;
        const int spp = QInputDialog::getInt(m_window, tr("Render to file"),
                                             tr("Samples per pixel (0: a time budget instead):"), 64, 0,
                                             1 << 20, 1, &ok);
        if (!ok) return;
        double seconds = 0.0;
        if (spp == 0) {
            seconds = QInputDialog::getDouble(m_window, tr("Render to file"), tr("Seconds:"), 60.0, 0.1, 1e6, 1, &ok);
            if (!ok) return;
        }
        this->renderToFile(path, {spp, seconds}, true, [](const QString&) {});
    });
    connect(m_recent, &RecentFiles::changed, this, [this] { rebuildRecentMenu(); });
    connect(window->document(), &SceneDocument::sceneOpened, this, [this](auto, const QString& path) {
        m_recent->add(path);
    });
    connect(window->document(), &SceneDocument::saved, this, [this](const QString& path) { m_recent->add(path); });
    connect(m_render, &RenderToFile::progress, this, [this](double fraction, const QString& text) {
        if (!m_progress) return;
        // The label first: a modal dialog's setValue() processes events, and the render's queued
        // `finished` handled there drops m_progress (CI crashed in setLabelText after it).
        m_progress->setLabelText(text);
        m_progress->setValue(int(fraction * 1000.0));
    });
    connect(m_render, &RenderToFile::finished, this, [this](const QString& path, const QString& error) {
        if (m_progress) {
            m_progress->deleteLater();
            m_progress = nullptr;
        }
        Done done = std::move(m_renderDone);
        m_renderDone = nullptr;
        const QString result = error == "cancelled" ? error : finish(tr("Render to file"), error.isEmpty() ? error : naming(path, error));
        if (result.isEmpty()) m_window->statusBar()->showMessage(tr("Rendered %1").arg(path), 5000);
        if (done) done(result);
    });

    window->properties()->setFolderFor([this](scene::EntityKind kind) -> QString {
        auto scene = m_window->document()->scene();
        const QString path = m_window->document()->path();
        if (!scene || path.isEmpty()) return {};
        return kind == EntityKind::Environment ? environmentBase(*scene, path) : folderOf(path);
    });
    window->setAcceptDrops(true);
    window->installEventFilter(this);
}

QString FileActions::finish(const QString& title, const QString& error) {
    if (!error.isEmpty()) {
        m_lastError = error;
        ++m_failures;
        m_window->errors()->report(title, error);
    }
    return error;
}

QString FileActions::absoluteFromScene(const QString& path) const {
    if (QFileInfo(path).isAbsolute()) return QDir::cleanPath(path);
    const QString scenePath = m_window->document()->path();
    return QDir::cleanPath(QDir(scenePath.isEmpty() ? QDir::currentPath() : folderOf(scenePath)).filePath(path));
}

void FileActions::newScene() { m_window->document()->newScene(); }

void FileActions::rebuildRecentMenu() {
    m_recentMenu->clear();
    int n = 0;
    for (const QString& path : m_recent->files()) {
        QAction* a = m_recentMenu->addAction(QStringLiteral("&%1 %2").arg(++n).arg(QFileInfo(path).fileName()));
        a->setObjectName(QStringLiteral("actionRecent%1").arg(n));
        a->setToolTip(path);
        connect(a, &QAction::triggered, this, [this, path] {
            m_window->actions()->prompt()->ask(tr("open another scene"),
                                               [this, path] { m_window->document()->open(path); });
        });
    }
    m_recentMenu->addSeparator();
    QAction* clear = m_recentMenu->addAction(tr("Clear list"));
    clear->setObjectName("actionClearRecent");
    clear->setEnabled(n > 0);
    connect(clear, &QAction::triggered, m_recent, &RecentFiles::clear);
}

void FileActions::saveLighting(const QString& path, Done done) {
    auto scene = m_window->document()->scene();
    if (!scene) return done(finish(tr("Save lighting setup"), tr("No scene is open.")));
    if (QFileInfo(path).suffix() != "wllight")
        return done(finish(tr("Save lighting setup"), naming(path, tr("a lighting setup is saved as *.wllight"))));
    scene::LightingSetup setup = scene->lighting;
    const QString target = QFileInfo(path).absoluteFilePath();
    if (!setup.environment.path.empty()) {
        const QString map = QDir(environmentBase(*scene, m_window->document()->path()))
                                .filePath(QString::fromStdString(setup.environment.path));
        setup.environment.path = QDir(folderOf(target)).relativeFilePath(map).toStdString();
    }
    runInBackground(this, [setup, target] {
        auto status = scene::saveLightingSetup(setup, target.toStdString());
        return status ? QString() : naming(target, message(status.error()));
    }, [this, done](const QString& error) { done(finish(tr("Save lighting setup"), error)); });
}

void FileActions::applyLighting(const QString& path, Done done) {
    auto scene = m_window->document()->scene();
    const QString scenePath = m_window->document()->path();
    if (!scene) return done(finish(tr("Apply lighting setup"), tr("No scene is open.")));
    if (scenePath.isEmpty())
        return done(finish(tr("Apply lighting setup"),
                           tr("Save the scene first: it refers to the setup by a path relative to its file.")));
    const QString file = absoluteFromScene(path);
    runInBackground(this, [scene, scenePath, file]() -> std::pair<QString, LightingState> {
        scene::Scene copy = *scene;
        auto status = scene::attachLightingSetup(copy, scenePath.toStdString(), file.toStdString());
        if (!status) return {naming(file, message(status.error())), {}};
        return {QString(), LightingState{copy.lighting, copy.lightingPath, copy.lighting}};
    }, [this, done, file](const std::pair<QString, LightingState>& result) {
        if (!result.first.isEmpty()) return done(finish(tr("Apply lighting setup"), result.first));
        auto status = m_window->document()->applyLighting(
            result.second, tr("apply lighting %1").arg(QFileInfo(file).fileName()));
        done(finish(tr("Apply lighting setup"), status ? QString() : message(status.error())));
    });
}

void FileActions::setEnvironmentMap(const QString& path, Done done) {
    auto scene = m_window->document()->scene();
    const QString scenePath = m_window->document()->path();
    if (!scene) return done(finish(tr("Environment map"), tr("No scene is open.")));
    if (scenePath.isEmpty())
        return done(finish(tr("Environment map"), tr("Save the scene first: the map's path is relative to its file.")));
    const QString file = absoluteFromScene(path);
    const QString relative = QDir(environmentBase(*scene, scenePath)).relativeFilePath(file);
    runInBackground(this, [file] {
        auto image = scene::loadImage(file.toStdString()); // the check: the render thread loads it again
        return image ? QString() : naming(file, message(image.error()));
    }, [this, done, relative](const QString& error) {
        if (!error.isEmpty()) return done(finish(tr("Environment map"), error));
        auto status = m_window->document()->apply(
            {{EntityKind::Environment, scene::kInvalidId}, "map", relative.toStdString()});
        done(finish(tr("Environment map"), status ? QString() : message(status.error())));
    });
}

void FileActions::addObject(const QString& path, const QString& name, Done done) {
    auto scene = m_window->document()->scene();
    const QString scenePath = m_window->document()->path();
    if (!scene) return done(finish(tr("Add object"), tr("No scene is open.")));
    if (scenePath.isEmpty())
        return done(finish(tr("Add object"), tr("Save the scene first: the mesh path is relative to its file.")));
    const QString file = absoluteFromScene(path);
    const std::string relative = QDir(folderOf(scenePath)).relativeFilePath(file).toStdString();
    using Loaded = std::pair<QString, std::shared_ptr<const scene::TriangleMesh>>;
    runInBackground(this, [file]() -> Loaded {
        auto mesh = scene::loadMesh(file.toStdString());
        if (!mesh) return {naming(file, message(mesh.error())), nullptr};
        return {QString(), std::make_shared<const scene::TriangleMesh>(std::move(mesh).value())};
    }, [this, done, relative, name](const Loaded& loaded) {
        if (!loaded.first.isEmpty()) return done(finish(tr("Add object"), loaded.first));
        auto current = m_window->document()->scene(); // edits may have landed while loading
        auto changes = addObjectChange(*current, relative, loaded.second, name.toStdString());
        util::Status status = changes ? util::okStatus() : util::Status(changes.error());
        if (changes) {
            const auto added = addedEntity(*changes);
            status = m_window->document()->applyChanges(
                *changes, tr("add object %1").arg(QString::fromStdString(
                              std::get<scene::Object>(std::get<scene::EntityEdit>(changes->edits().back()).entity).name)));
            if (status && added) m_window->outline()->select(*added);
        }
        done(finish(tr("Add object"), status ? QString() : message(status.error())));
    });
}

void FileActions::openDropped(const QString& path, Done done) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == "wlscene") {
        m_window->actions()->prompt()->ask(tr("open another scene"), [this, path] { m_window->document()->open(path); });
        return done(QString());
    }
    if (suffix == "wllight") return applyLighting(path, std::move(done));
    if (suffix == "exr" || suffix == "hdr") return setEnvironmentMap(path, std::move(done));
    if (suffix == "obj") return addObject(path, QString(), std::move(done));
    done(finish(tr("Drop"), naming(path, tr("cannot open a '.%1' file here: drop a .wlscene, .wllight, .exr, .hdr "
                                            "or .obj").arg(suffix))));
}

void FileActions::renderToFile(const QString& path, RenderBudget budget, bool showProgress, Done done) {
    auto scene = m_window->document()->scene();
    const RenderSettings& settings = m_window->renderer()->settings();
    render::RenderOptions options;
    if (scene) {
        options.width = settings.width > 0 ? settings.width : scene->render.width;
        options.height = settings.height > 0 ? settings.height : scene->render.height;
        options.bounces = scene->render.bounces;
    }
    options.device = settings.device;
    options.sampler = settings.sampler;
    options.validation = settings.validation;
    QString error;
    if (!m_render->start(scene, options, budget, QFileInfo(path).absoluteFilePath(),
                         m_window->viewport()->exposure(), &error))
        return done(finish(tr("Render to file"), error));
    m_renderDone = std::move(done);
    if (showProgress) {
        m_progress = new QProgressDialog(tr("Rendering %1…").arg(QFileInfo(path).fileName()), tr("Cancel"), 0,
                                         1000, m_window);
        m_progress->setObjectName("renderProgress");
        m_progress->setWindowModality(Qt::WindowModal);
        m_progress->setMinimumDuration(0);
        connect(m_progress, &QProgressDialog::canceled, m_render, &RenderToFile::cancel);
        m_progress->show();
    }
}

bool FileActions::eventFilter(QObject* watched, QEvent* event) {
    if (watched != m_window) return false;
    auto paths = [](const QMimeData* mime) {
        QStringList out;
        for (const QUrl& url : mime->urls())
            if (url.isLocalFile()) out << url.toLocalFile();
        return out;
    };
    if (event->type() == QEvent::DragEnter) {
        auto* drag = static_cast<QDragEnterEvent*>(event);
        for (const QString& p : paths(drag->mimeData()))
            if (kDroppable.contains(QFileInfo(p).suffix().toLower())) {
                drag->acceptProposedAction();
                return true;
            }
        return false;
    }
    if (event->type() == QEvent::Drop) {
        auto* drop = static_cast<QDropEvent*>(event);
        for (const QString& p : paths(drop->mimeData())) {
            ++m_pendingDrops;
            openDropped(p, [this](const QString&) { --m_pendingDrops; });
        }
        drop->acceptProposedAction();
        return true;
    }
    return false;
}

} // namespace wavelit::editor
