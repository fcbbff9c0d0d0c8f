#include "app/outline_actions.h"

#include "app/editor_actions.h"
#include "app/error_reporter.h"
#include "app/file_actions.h"
#include "app/main_window.h"
#include "app/outline_edits.h"
#include "app/scene_document.h"
#include "panels/outline_panel.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QTreeWidget>

namespace wavelit::editor {
namespace {

QString nameOf(const scene::Scene& scene, EntityRef ref) {
    return QString::fromStdString(entityName(scene, ref));
}

} // namespace

OutlineActions::OutlineActions(MainWindow* window) : QObject(window), m_window(window) {
    setObjectName("outlineActions");
    QMenu* edit = window->actions()->editMenu();
    edit->addSeparator();
    QMenu* add = edit->addMenu(tr("&Add"));
    add->setObjectName("menuAdd");
    auto make = [&](QMenu* menu, const QString& name, const QString& text, const QKeySequence& key = {}) {
        auto* a = new QAction(text, window);
        a->setObjectName(name);
        a->setShortcut(key);
        if (key.isEmpty()) window->addAction(a); // keyed ones belong to the outline (below)
        menu->addAction(a);
        return a;
    };
    const std::pair<const char*, QString> lights[] = {
        {"point", tr("Point light")}, {"sphere", tr("Sphere light")}, {"rect", tr("Rect light")},
        {"spot", tr("Spot light")},   {"sun", tr("Sun")}};
    for (const auto& [type, label] : lights) {
        QString name = QString("actionAdd%1Light").arg(QString(type).left(1).toUpper() + QString(type).mid(1));
        connect(make(add, name, label), &QAction::triggered, this, [this, type = QString(type)] {
            if (auto r = addLight(type, {}); !r) report(tr("Add light"), r.error());
        });
    }
    add->addSeparator();
    connect(make(add, "actionAddObject", tr("Object from mesh file…")), &QAction::triggered, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            m_window, tr("Add object"), QFileInfo(m_window->document()->path()).absolutePath(),
            tr("Meshes (*.obj *.ply *.gltf *.glb *.fbx);;All files (*)"));
        if (!path.isEmpty()) m_window->files()->addObject(path, {}, [](const QString&) {});
    });
    connect(make(add, "actionAddMaterial", tr("Material")), &QAction::triggered, this, [this] {
        if (auto r = addMaterial({}); !r) report(tr("Add material"), r.error());
    });
    QAction* del = make(edit, "actionDelete", tr("&Delete"), QKeySequence::Delete);
    QAction* dup = make(edit, "actionDuplicate", tr("D&uplicate"), QKeySequence(Qt::CTRL | Qt::Key_D));
    QAction* ren = make(edit, "actionRename", tr("Re&name…"), QKeySequence(Qt::Key_F2));
    for (QAction* a : {del, dup, ren}) a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    // Del, Ctrl+D and F2 act on the outline's selection while the outline has the focus (a Del in
    // a property's text field deletes text).
    for (QAction* a : {del, dup, ren}) window->outline()->addAction(a);
    connect(del, &QAction::triggered, this, [this] {
        if (auto ref = m_window->outline()->selectedEntity()) report(tr("Delete"), remove(*ref));
    });
    connect(dup, &QAction::triggered, this, [this] {
        if (auto ref = m_window->outline()->selectedEntity())
            if (auto r = duplicate(*ref); !r) report(tr("Duplicate"), r.error());
    });
    connect(ren, &QAction::triggered, this, [this] {
        auto ref = m_window->outline()->selectedEntity();
        auto scene = m_window->document()->scene();
        if (!ref || !scene) return;
        bool ok = false;
        const QString name = QInputDialog::getText(m_window, tr("Rename"), tr("New name:"), QLineEdit::Normal,
                                                   nameOf(*scene, *ref), &ok);
        if (ok) report(tr("Rename"), rename(*ref, name));
    });
    // The same actions on the outline's right-click menu.
    QTreeWidget* tree = window->outline()->tree();
    tree->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(tree, &QWidget::customContextMenuRequested, this, [tree, add, del, dup, ren](const QPoint& at) {
        QMenu menu;
        menu.addMenu(add);
        menu.addSeparator();
        menu.addActions({dup, ren, del});
        menu.exec(tree->viewport()->mapToGlobal(at));
    });
}

void OutlineActions::report(const QString& title, const util::Status& status) {
    if (!status) m_window->errors()->report(title, QString::fromStdString(status.error().message()));
}

util::Result<EntityRef> OutlineActions::push(util::Result<scene::ChangeSet> changes, const QString& text) {
    if (!changes) return changes.error();
    const auto added = addedEntity(*changes);
    if (auto status = m_window->document()->applyChanges(*changes, text); !status) return status.error();
    if (added) m_window->outline()->select(*added);
    return added.value_or(EntityRef{});
}

util::Result<EntityRef> OutlineActions::addLight(const QString& type, const QString& name) {
    auto scene = m_window->document()->scene();
    if (!scene) return util::makeError(util::ErrorKind::Invalid, "", "no scene is open");
    const auto parsed = parseLightType(type.toStdString());
    if (!parsed)
        return util::makeError(util::ErrorKind::Invalid, "",
                               "unknown light type '" + type.toStdString() + "'; known: point, sphere, rect, spot, sun");
    auto changes = addLightChange(*scene, *parsed, name.toStdString());
    QString added = name;
    if (changes)
        if (auto ref = addedEntity(*changes))
            added = QString::fromStdString(std::get<scene::Light>(std::get<scene::EntityEdit>(changes->edits().back()).entity).name);
    return push(std::move(changes), tr("add light %1").arg(added));
}

util::Result<EntityRef> OutlineActions::addMaterial(const QString& name) {
    auto scene = m_window->document()->scene();
    if (!scene) return util::makeError(util::ErrorKind::Invalid, "", "no scene is open");
    return push(addMaterialChange(*scene, name.toStdString()), tr("add material"));
}

util::Result<EntityRef> OutlineActions::duplicate(EntityRef ref) {
    auto scene = m_window->document()->scene();
    if (!scene) return util::makeError(util::ErrorKind::Invalid, "", "no scene is open");
    return push(duplicateChange(*scene, ref), tr("duplicate %1").arg(nameOf(*scene, ref)));
}

util::Status OutlineActions::remove(EntityRef ref) {
    auto scene = m_window->document()->scene();
    if (!scene) return util::makeError(util::ErrorKind::Invalid, "", "no scene is open");
    auto r = push(removeChange(*scene, ref),
                  tr("delete %1 %2").arg(scene::entityKindName(ref.kind), nameOf(*scene, ref)));
    return r ? util::okStatus() : util::Status(r.error());
}

util::Status OutlineActions::rename(EntityRef ref, const QString& name) {
    auto scene = m_window->document()->scene();
    if (!scene) return util::makeError(util::ErrorKind::Invalid, "", "no scene is open");
    if (auto status = checkRename(*scene, ref, name.toStdString()); !status) return status;
    return m_window->document()->apply({ref, "name", name.toStdString()});
}

} // namespace wavelit::editor
