#include "app/autosave_controller.h"

#include "app/error_reporter.h"
#include "app/scene_document.h"

#include <QDir>
#include <QPushButton>
#include <QtConcurrent/QtConcurrentRun>

#include <cstdio>

namespace wavelit::editor {
namespace {

int intervalMs() {
    bool ok = false;
    const int configured = qEnvironmentVariableIntValue("WAVELIT_AUTOSAVE_MS", &ok);
    return ok && configured > 0 ? configured : AutosaveController::kDefaultIntervalMs;
}

} // namespace

AutosaveController::AutosaveController(SceneDocument* document, ErrorReporter* errors,
                                       QWidget* dialogParent, RecoveryStore store)
    : QObject(dialogParent), m_document(document), m_errors(errors), m_parent(dialogParent),
      m_store(std::move(store)) {
    m_timer.setInterval(intervalMs());
    connect(&m_timer, &QTimer::timeout, this, [this] { autosaveNow(); });
    m_timer.start();
    connect(document, &SceneDocument::sceneOpened, this,
            [this](std::shared_ptr<const scene::Scene>, const QString& path) {
                m_written.reset();
                m_wroteThisDocument = false;
                if (!m_restoring) offer(path);
            });
    connect(document, &SceneDocument::saved, this, [this] { discardRecovery(); });
    // Undone back to the saved state: what this session autosaved is stale. (A recovery from an
    // earlier session the artist chose to keep is left alone.)
    connect(document, &SceneDocument::modifiedChanged, this, [this](bool modified) {
        if (!modified && m_wroteThisDocument) discardRecovery();
    });
}

AutosaveController::~AutosaveController() {
    // A write in flight finishes on its pool thread; its result is not needed any more.
    if (m_writing) m_writing->waitForFinished();
}

bool AutosaveController::autosaveNow() {
    auto scene = m_document->scene();
    if (!scene || !m_document->isModified() || scene == m_written || m_writing) return false;
    m_written = scene;
    const QString path = m_document->path();
    m_writing = new QFutureWatcher<QString>(this);
    connect(m_writing, &QFutureWatcherBase::finished, this, [this, path] {
        const QString error = m_writing->result();
        m_writing->deleteLater();
        m_writing = nullptr;
        if (!error.isEmpty()) {
            std::fprintf(stderr, "wavelit: autosave failed: %s\n", qPrintable(error));
            m_written.reset(); // try again next time
            return;
        }
        m_wroteThisDocument = true;
        m_writtenPath = path;
        emit autosaved(m_store.recoveryFileFor(path));
    });
    m_writing->setFuture(QtConcurrent::run([store = m_store, scene, path] {
        auto status = store.write(*scene, path);
        return status ? QString() : QString::fromStdString(status.error().message());
    }));
    return true;
}

void AutosaveController::discardRecovery() {
    if (m_writing) m_writing->waitForFinished(); // a late write must not resurrect it
    m_store.remove(m_document->path());
    if (m_wroteThisDocument) m_store.remove(m_writtenPath); // the document may have moved (Save As)
    m_written.reset();
    m_wroteThisDocument = false;
}

void AutosaveController::offer(const QString& scenePath) {
    const auto recovery = m_store.find(scenePath);
    if (!recovery) return;
    if (m_scripted) {
        answer(*m_scripted, *recovery);
        return;
    }
    if (!m_errors->dialogsEnabled()) {
        std::fprintf(stderr, "wavelit: '%s' has unsaved changes from %s in %s; kept (a script can "
                             "answer with app.answerRecovery(\"recover\"|\"discard\"|\"keep\"))\n",
                     qPrintable(scenePath), qPrintable(recovery->saved.toLocalTime().toString()),
                     qPrintable(recovery->recoveryFile));
        return;
    }
    auto* box = new QMessageBox(QMessageBox::Question, tr("Recover unsaved changes?"),
                                tr("%1 has unsaved changes from %2 that were not saved.")
                                    .arg(QDir::toNativeSeparators(scenePath),
                                         recovery->saved.toLocalTime().toString()),
                                QMessageBox::NoButton, m_parent);
    box->setObjectName("recoveryDialog");
    QPushButton* recover = box->addButton(tr("Recover"), QMessageBox::AcceptRole);
    QPushButton* discard = box->addButton(tr("Discard"), QMessageBox::DestructiveRole);
    box->addButton(tr("Keep for later"), QMessageBox::RejectRole);
    box->setDefaultButton(recover);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::finished, this, [this, box, recover, discard, r = *recovery](int) {
        const QAbstractButton* clicked = box->clickedButton();
        answer(clicked == recover ? RecoveryAnswer::Recover
               : clicked == discard ? RecoveryAnswer::Discard
                                    : RecoveryAnswer::Keep,
               r);
    });
    box->open();
    m_dialog = box;
}

void AutosaveController::answer(RecoveryAnswer answer, const Recovery& recovery) {
    switch (answer) {
    case RecoveryAnswer::Keep: return;
    case RecoveryAnswer::Discard: m_store.remove(recovery.scenePath); return;
    case RecoveryAnswer::Recover: {
        // Off the UI thread: a scene and its assets, the same cost as opening it.
        using Read = util::Result<RecoveredDocument>;
        auto* reading = new QFutureWatcher<std::shared_ptr<Read>>(this);
        connect(reading, &QFutureWatcherBase::finished, this, [this, reading, recovery] {
            reading->deleteLater();
            const std::shared_ptr<Read> read = reading->result();
            if (!*read) {
                m_errors->report(tr("Recover"), QString::fromStdString(read->error().message()));
                return;
            }
            m_restoring = true; // the document "opens" again: do not offer this recovery twice
            m_document->restoreRecovered((*read)->scene, recovery.scenePath, (*read)->savedLighting);
            m_restoring = false;
            emit recovered(recovery.scenePath);
        });
        reading->setFuture(QtConcurrent::run(
            [store = m_store, recovery] { return std::make_shared<Read>(store.read(recovery)); }));
        return;
    }
    }
}

} // namespace wavelit::editor
