// AutosaveController: no crash loses an artist's work. While the document has unsaved edits it is
// written to its recovery file (app/recovery_store.h) every interval (kDefaultIntervalMs, or
// WAVELIT_AUTOSAVE_MS) and at once when the render thread fails; writes run on a pool thread.
// Saving, or leaving the document with "Discard", removes the recovery. When a scene opens for
// which a recovery newer than the file exists, the controller offers it: Recover (the document
// becomes the recovered state, modified), Discard (the recovery is deleted) or Keep (asked again
// next time). Scripts answer with setScriptedAnswer (app.answerRecovery); while a script runs
// without an answer, the recovery is kept and a line on stderr says so.
#pragma once

#include "app/recovery_store.h"

#include <QFutureWatcher>
#include <QMessageBox>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <memory>
#include <optional>

namespace wavelit::editor {

class ErrorReporter;
class SceneDocument;

enum class RecoveryAnswer { Recover, Discard, Keep };

class AutosaveController : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultIntervalMs = 30000;

    AutosaveController(SceneDocument* document, ErrorReporter* errors, QWidget* dialogParent,
                       RecoveryStore store = RecoveryStore());
    ~AutosaveController() override;

    const RecoveryStore& store() const { return m_store; }
    // Writes the recovery now if the document has edits not yet written; false if nothing to do.
    bool autosaveNow();
    bool isWriting() const { return m_writing != nullptr; }
    // The document is being left on purpose (saved or discarded): its recovery goes.
    void discardRecovery();

    void setScriptedAnswer(std::optional<RecoveryAnswer> answer) { m_scripted = answer; }
    QMessageBox* currentDialog() const { return m_dialog; }

signals:
    void autosaved(const QString& recoveryFile);
    void recovered(const QString& scenePath);

private:
    void offer(const QString& scenePath);
    void answer(RecoveryAnswer answer, const Recovery& recovery);

    SceneDocument* m_document;
    ErrorReporter* m_errors;
    QWidget* m_parent;
    RecoveryStore m_store;
    QTimer m_timer;
    std::shared_ptr<const scene::Scene> m_written; // the snapshot last written
    QFutureWatcher<QString>* m_writing = nullptr;  // empty result = success
    std::optional<RecoveryAnswer> m_scripted;
    QPointer<QMessageBox> m_dialog;
    bool m_restoring = false;
    bool m_wroteThisDocument = false; // a recovery of the open document was written this session
    QString m_writtenPath;            // ... keyed by this scene path
};

} // namespace wavelit::editor
