// ErrorReporter: every user-facing error ends here (architecture.md §9: errors -> a dialog). Shows a
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
    // Something the user should read that is not a failure (a file opened with repairs): a
    // warning dialog, logged; not counted as an error and not emitted as `reported`.
    void warn(const QString& title, const QString& message);

    QString lastMessage() const { return m_lastMessage; }
    int count() const { return m_count; }
    // The dialog of the most recent report while it is open; null once closed.
    QMessageBox* currentDialog() const { return m_dialog; }
    // Scripts and headless runs log errors instead of showing dialogs.
    void setDialogsEnabled(bool enabled) { m_dialogsEnabled = enabled; }
    bool dialogsEnabled() const { return m_dialogsEnabled; }

signals:
    void reported(const QString& message);

private:
    void show(QMessageBox::Icon icon, const QString& objectName, const QString& title,
              const QString& message);

    QWidget* m_parent;
    QPointer<QMessageBox> m_dialog;
    QString m_lastMessage;
    int m_count = 0;
    bool m_dialogsEnabled = true;
};

} // namespace wavelit::editor
