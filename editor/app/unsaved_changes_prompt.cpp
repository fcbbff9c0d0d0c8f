#include "app/unsaved_changes_prompt.h"

#include "app/error_reporter.h"
#include "app/scene_document.h"

#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>

#include <cstdio>
#include <memory>

namespace wavelit::editor {

UnsavedChangesPrompt::UnsavedChangesPrompt(QWidget* dialogParent, SceneDocument* document,
                                           ErrorReporter* errors, std::function<bool()> saveDocument)
    : QObject(dialogParent), m_parent(dialogParent), m_document(document), m_errors(errors),
      m_saveDocument(std::move(saveDocument)) {}

void UnsavedChangesPrompt::ask(const QString& action, std::function<void()> proceed) {
    if (!m_document->isModified()) {
        proceed();
        return;
    }
    ++m_asked;
    if (m_scripted) {
        answer(*m_scripted, std::move(proceed));
        return;
    }
    if (!m_errors->dialogsEnabled()) {
        std::fprintf(stderr, "wavelit: unsaved changes: %s cancelled (a script can answer with "
                             "app.answerPrompts(\"save\"|\"discard\"|\"cancel\"))\n",
                     qPrintable(action));
        return;
    }
    if (m_dialog) return; // already asking
    const QString name = m_document->path().isEmpty() ? tr("The scene") : QFileInfo(m_document->path()).fileName();
    QString text = tr("%1 has unsaved changes.").arg(name);
    if (m_document->lightingEdited()) text += tr(" Its lighting setup was edited too.");
    auto* box = new QMessageBox(QMessageBox::Question, tr("Save changes?"), text,
                                QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, m_parent);
    box->setObjectName("saveChangesDialog");
    box->setInformativeText(tr("Save the changes before you %1?").arg(action));
    box->setDefaultButton(QMessageBox::Save);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::finished, this, [this, box, proceed = std::move(proceed)](int) {
        const auto button = box->standardButton(box->clickedButton());
        answer(button == QMessageBox::Save      ? PromptAnswer::Save
               : button == QMessageBox::Discard ? PromptAnswer::Discard
                                                : PromptAnswer::Cancel,
               proceed);
    });
    box->open();
    m_dialog = box;
}

void UnsavedChangesPrompt::answer(PromptAnswer answer, std::function<void()> proceed) {
    switch (answer) {
    case PromptAnswer::Cancel: return;
    case PromptAnswer::Discard: proceed(); return;
    case PromptAnswer::Save: {
        // Proceed once this save lands; a failure is reported by the document's saveFailed.
        auto connections = std::make_shared<std::pair<QMetaObject::Connection, QMetaObject::Connection>>();
        auto done = [connections] {
            disconnect(connections->first);
            disconnect(connections->second);
        };
        connections->first = connect(m_document, &SceneDocument::saved, this, [done, proceed] {
            done();
            proceed();
        });
        connections->second = connect(m_document, &SceneDocument::saveFailed, this, [done] { done(); });
        if (!m_saveDocument()) done();
        return;
    }
    }
}

} // namespace wavelit::editor
