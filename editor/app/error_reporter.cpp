#include "app/error_reporter.h"

#include <QMessageBox>

#include <cstdio>

namespace wavelit::editor {

ErrorReporter::ErrorReporter(QWidget* dialogParent) : QObject(dialogParent), m_parent(dialogParent) {}

void ErrorReporter::report(const QString& title, const QString& message) {
    m_lastMessage = message;
    ++m_count;
    show(QMessageBox::Critical, "errorDialog", title, message);
    emit reported(message);
}

void ErrorReporter::warn(const QString& title, const QString& message) {
    show(QMessageBox::Warning, "warningDialog", title, message);
}

void ErrorReporter::show(QMessageBox::Icon icon, const QString& objectName, const QString& title,
                         const QString& message) {
    std::fprintf(stderr, "wavelit: %s: %s\n", qPrintable(title), qPrintable(message));
    if (!m_dialogsEnabled) return;
    auto* box = new QMessageBox(icon, title, message, QMessageBox::Ok, m_parent);
    box->setObjectName(objectName);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
    m_dialog = box;
}

} // namespace wavelit::editor
