// ErrorReporter: every user-facing error ends here (STYLE.md: errors -> a dialog). Shows a
// window-modal QMessageBox with open(), never exec(), so no nested event loop runs inside a slot
// and tests (or scripts) can read the dialog and close it. Also logs to stderr and remembers the
// last message for the script API.
#pragma once

#include <QObject>
#include <QPointer>
#include <QString>

#include <QMessageBox>
class QWidget;

namespace wavelit::editor {

class ErrorReporter : public QObject {
    Q_OBJECT
public:
    explicit ErrorReporter(QWidget* dialogParent);

    void report(const QString& title, const QString& message);

    QString lastMessage() const { return m_lastMessage; }
    int count() const { return m_count; }
    // The dialog of the most recent report while it is open; null once closed.
    QMessageBox* currentDialog() const { return m_dialog; }
    // Scripts and headless runs log errors instead of showing dialogs.
    void setDialogsEnabled(bool enabled) { m_dialogsEnabled = enabled; }

signals:
    void reported(const QString& message);

private:
    QWidget* m_parent;
    QPointer<QMessageBox> m_dialog;
    QString m_lastMessage;
    int m_count = 0;
    bool m_dialogsEnabled = true;
};

} // namespace wavelit::editor
