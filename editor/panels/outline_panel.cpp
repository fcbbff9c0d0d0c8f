#include "panels/outline_panel.h"

#include <QGuiApplication>
#include <QHeaderView>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QVBoxLayout>

namespace wavelit::editor {
namespace {

constexpr int kEntityRole = Qt::UserRole + 1;

QTreeWidgetItem* addItem(QTreeWidgetItem* parent, const QString& text, EntityRef ref,
                         const QString& kindLabel) {
    auto* item = new QTreeWidgetItem(parent, QStringList{text, kindLabel});
    item->setData(0, kEntityRole, QVariant::fromValue(ref));
    return item;
}

QTreeWidgetItem* addGroup(QTreeWidget* tree, const QString& text) {
    auto* item = new QTreeWidgetItem(tree, QStringList{text});
    item->setFlags(item->flags() & ~Qt::ItemIsSelectable);
    QFont font = item->font(0);
    font.setBold(true);
    item->setFont(0, font);
    return item;
}

QString lightTypeLabel(scene::LightType type) {
    switch (type) {
    case scene::LightType::Point: return "point light";
    case scene::LightType::Sphere: return "sphere light";
    case scene::LightType::Rect: return "rect light";
    case scene::LightType::Spot: return "spot light";
    case scene::LightType::Sun: return "sun";
    }
    return "light";
}

} // namespace

OutlinePanel::OutlinePanel(QWidget* parent) : QWidget(parent), m_tree(new QTreeWidget(this)) {
    setObjectName("outlinePanel");
    m_tree->setObjectName("outlineTree");
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Name"), tr("Kind")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tree);
    connect(m_tree, &QTreeWidget::itemSelectionChanged, this,
            [this] { emit entitySelected(selectedEntity()); });
    // Only user clicks reach here: setScene rebuilds the items with signals blocked.
    connect(m_tree, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        const QVariant data = item->data(0, kEntityRole);
        if (column != 0 || !data.isValid() || data.value<EntityRef>().kind != EntityKind::Light)
            return;
        const scene::EntityId id = data.value<EntityRef>().id;
        const bool solo = QGuiApplication::queryKeyboardModifiers() & Qt::AltModifier;
        const bool muted = item->checkState(0) != Qt::Checked;
        // Queued: the edit rebuilds the tree (setScene), which must not delete the item whose
        // signal is being delivered.
        QMetaObject::invokeMethod(this, [this, id, solo, muted] {
            if (solo) emit soloRequested(id);
            else emit muteRequested(id, muted);
        }, Qt::QueuedConnection);
    });
}

void OutlinePanel::clear() { m_tree->clear(); }

void OutlinePanel::setScene(const scene::Scene& scene) {
    const std::optional<EntityRef> previous = selectedEntity();
    const QSignalBlocker blocker(m_tree);
    m_tree->clear();
    auto* camera = new QTreeWidgetItem(m_tree, QStringList{tr("Camera"), tr("camera")});
    camera->setData(0, kEntityRole, QVariant::fromValue(EntityRef{EntityKind::Camera, 0}));
    auto* render = new QTreeWidgetItem(m_tree, QStringList{tr("Render settings"), tr("render")});
    render->setData(0, kEntityRole, QVariant::fromValue(EntityRef{EntityKind::Render, 0}));

    auto* lighting = addGroup(m_tree, tr("Lighting"));
    addItem(lighting, tr("Environment"), {EntityKind::Environment, 0}, tr("environment"));
    for (const auto& light : scene.lighting.lights) {
        auto* item = addItem(lighting, QString::fromStdString(light.name),
                             {EntityKind::Light, light.id}, lightTypeLabel(light.type));
        item->setCheckState(0, light.muted ? Qt::Unchecked : Qt::Checked);
        item->setToolTip(0, tr("Check: emits; uncheck: mute; Alt-click: solo"));
    }

    auto* objects = addGroup(m_tree, tr("Objects"));
    for (const auto& object : scene.objects)
        addItem(objects, QString::fromStdString(object.name), {EntityKind::Object, object.id},
                tr("mesh"));

    auto* materials = addGroup(m_tree, tr("Materials"));
    for (const auto& material : scene.materials)
        addItem(materials, QString::fromStdString(material.name),
                {EntityKind::Material, material.id}, QString::fromStdString(material.brdf));

    m_tree->expandAll();
    m_tree->resizeColumnToContents(1);
    if (previous)
        if (auto* item = findItem(*previous)) item->setSelected(true);
}

std::optional<EntityRef> OutlinePanel::selectedEntity() const {
    const auto items = m_tree->selectedItems();
    if (items.isEmpty()) return std::nullopt;
    const QVariant data = items.front()->data(0, kEntityRole);
    if (!data.isValid()) return std::nullopt;
    return data.value<EntityRef>();
}

bool OutlinePanel::select(EntityRef ref) {
    QTreeWidgetItem* item = findItem(ref);
    if (!item) return false;
    m_tree->setCurrentItem(item);
    return true;
}

QTreeWidgetItem* OutlinePanel::findItem(EntityRef ref) const {
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        const QVariant data = (*it)->data(0, kEntityRole);
        if (data.isValid() && data.value<EntityRef>() == ref) return *it;
    }
    return nullptr;
}

QStringList OutlinePanel::namesUnder(const QString& group) const {
    QStringList names;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        const QTreeWidgetItem* top = m_tree->topLevelItem(i);
        if (top->text(0) != group) continue;
        for (int c = 0; c < top->childCount(); ++c) names << top->child(c)->text(0);
    }
    return names;
}

} // namespace wavelit::editor
