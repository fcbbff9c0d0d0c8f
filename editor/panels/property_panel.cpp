#include "panels/property_panel.h"

#include "panels/property_rows.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace wavelit::editor {
namespace {

QString tooltipFor(const scene::PropertyInfo& info) {
    return QStringLiteral("%1\n(%2: %3%4)")
        .arg(QString::fromStdString(info.tooltip), QString::fromStdString(info.name),
             scene::propertyTypeName(info.type),
             info.unit.empty() ? QString() : QStringLiteral(", ") + QString::fromStdString(info.unit));
}

} // namespace

PropertyPanel::PropertyPanel(QWidget* parent)
    : QWidget(parent), m_title(new QLabel(this)), m_table(new QTableWidget(0, 2, this)),
      m_message(new QLabel(this)) {
    setObjectName("propertyPanel");
    m_title->setObjectName("propertyTitle");
    m_table->setObjectName("propertyTable");
    m_table->setHorizontalHeaderLabels({tr("Property"), tr("Value")});
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_title);
    layout->addWidget(m_table);
    m_message->setObjectName("propertyMessage");
    m_message->setWordWrap(true);
    m_message->setStyleSheet("color: #c0392b");
    m_message->hide();
    layout->addWidget(m_message);
    clear();
}

QString PropertyPanel::title() const { return m_title->text(); }

QString PropertyPanel::message() const { return m_message->text(); }

void PropertyPanel::showMessage(const QString& text) {
    m_message->setText(text);
    m_message->setVisible(!text.isEmpty());
    if (!text.isEmpty()) emit valueRefused(text);
}

QWidget* PropertyPanel::editorFor(const QString& propertyName) const {
    // Cell widgets of replaced rows are deleted later, so search the current rows only.
    for (int i = 0; i < m_table->rowCount(); ++i)
        if (QWidget* w = m_table->cellWidget(i, 1); w && w->objectName() == "edit_" + propertyName)
            return w;
    return nullptr;
}

void PropertyPanel::clear() {
    m_title->setText(tr("Nothing selected"));
    m_table->setRowCount(0);
    m_shown.reset();
    m_infos.clear();
    m_editors.clear();
}

void PropertyPanel::showEntity(const scene::Scene& scene, std::optional<EntityRef> ref) {
    if (!ref) {
        clear();
        return;
    }
    const auto rows = propertyRows(scene, *ref);
    bool sameRows = m_shown == ref && rows.size() == m_infos.size();
    for (size_t i = 0; sameRows && i < rows.size(); ++i) sameRows = rows[i].info == m_infos[i];
    if (!sameRows) {
        rebuild(scene, *ref);
    } else {
        const void* entity = scene::findEntity(scene, *ref);
        for (size_t i = 0; i < rows.size(); ++i)
            if (m_editors[i].show) m_editors[i].show(m_infos[i]->get(entity));
    }
    m_title->setText(QStringLiteral("%1 (%2)").arg(QString::fromStdString(entityName(scene, *ref)),
                                                   scene::entityKindName(ref->kind)));
}

void PropertyPanel::rebuild(const scene::Scene& scene, EntityRef ref) {
    const auto rows = propertyRows(scene, ref);
    const void* entity = scene::findEntity(scene, ref);
    m_table->setRowCount(0); // deletes the old editor widgets
    m_table->setRowCount(int(rows.size()));
    m_shown = ref;
    m_infos.clear();
    m_editors.clear();
    for (int i = 0; i < int(rows.size()); ++i) {
        const scene::PropertyInfo& info = *rows[size_t(i)].info;
        // Scalar editors show their unit as a suffix; vector rows show it in the label.
        const bool vector = info.type == scene::PropertyType::Vec2 ||
                            info.type == scene::PropertyType::Vec3 ||
                            info.type == scene::PropertyType::Color;
        QString text = QString::fromStdString(info.label);
        if (vector && !info.unit.empty()) text += " (" + QString::fromStdString(info.unit) + ")";
        auto* label = new QTableWidgetItem(text);
        label->setToolTip(tooltipFor(info));
        m_table->setItem(i, 0, label);
        PropertyEditor editor;
        if (info.set) {
            const std::string name = info.name;
            EditorContext context;
            context.refuse = [this](const QString& text) { showMessage(text); };
            context.folder = [this](scene::EntityKind kind) { return m_folderFor ? m_folderFor(kind) : QString(); };
            editor = createPropertyEditor(
                info, scene,
                [this, ref, name](const scene::PropertyValue& v, GestureId gesture) {
                    showMessage({}); // an accepted value clears an old refusal
                    emit editRequested(PropertyEdit{ref, name, v, gesture});
                },
                m_table, context);
            editor.show(info.get(entity));
            m_table->setCellWidget(i, 1, editor.widget);
        } else {
            m_table->setItem(i, 1, new QTableWidgetItem(QString::fromStdString(rows[size_t(i)].value)));
        }
        m_infos.push_back(&info);
        m_editors.push_back(std::move(editor));
    }
    m_table->resizeColumnToContents(0);
    m_table->resizeRowsToContents();
}

} // namespace wavelit::editor
