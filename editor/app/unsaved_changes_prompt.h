// UnsavedChangesPrompt: "Save changes?" (Save / Discard / Cancel) before the document is left —
// closing the window, quitting, opening another scene. ask() returns at once; `proceed` runs when
// the document may be left: at once when there is nothing to save or the answer is Discard, after
// the save succeeded for Save, never for Cancel or a failed save. The dialog is window-modal and
// opened with open(), never exec(), so no nested event loop runs inside the caller's slot.
//
// Scripts answer without a dialog: setScriptedAnswer() (app.answerPrompts) answers every prompt
// until cleared. While dialogs are off (a script runs) and no answer is set, the answer is Cancel
// and a line on stderr says so: nothing is lost, nothing waits for a click.
#pragma once

#include <QMessageBox>
#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>
#include <optional>

class QWidget;

namespace wavelit::editor {

class ErrorReporter;
class SceneDocument;

enum class PromptAnswer { Save, Discard, Cancel };

class UnsavedChangesPrompt : public QObject {
    Q_OBJECT
public:
    // `saveDocument` starts a save (Save, or Save As for a document without a file) and returns
    // false when none started (the user cancelled the file dialog).
    UnsavedChangesPrompt(QWidget* dialogParent, SceneDocument* document, ErrorReporter* errors,
                         std::function<bool()> saveDocument);

    // `action`: what the user is about to do ("close", "open another scene"), for the message.
    void ask(const QString& action, std::function<void()> proceed);

    void setScriptedAnswer(std::optional<PromptAnswer> answer) { m_scripted = answer; }
    QMessageBox* currentDialog() const { return m_dialog; }
    int timesAsked() const { return m_asked; }

private:
    void answer(PromptAnswer answer, std::function<void()> proceed);

    QWidget* m_parent;
    SceneDocument* m_document;
    ErrorReporter* m_errors;
    std::function<bool()> m_saveDocument;
    std::optional<PromptAnswer> m_scripted;
    QPointer<QMessageBox> m_dialog;
    int m_asked = 0;
};

} // namespace wavelit::editor
