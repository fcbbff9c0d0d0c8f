#include "app/error_reporter.h"

#include <QMessageBox>

#include <cstdio>

namespace wavelit::editor {

ErrorReporter::ErrorReporter(QWidget* dialogParent) : QObject(dialogParent), m_parent(dialogParent) {}

void ErrorReporter::report(const QString& title, const QString& message) {
    m_lastMessage = message;
    ++m_count;
    std::fprintf(stderr, "wavelit: %s: %s\n", qPrintable(title), qPrintable(message));
    if (m_dialogsEnabled) {
        auto* box = new QMessageBox(QMessageBox::Critical, title, message, QMessageBox::Ok, m_parent);
        box->setObjectName("errorDialog");
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        m_dialog = box;
    }
    emit reported(message);
}

} // namespace wavelit::editor
