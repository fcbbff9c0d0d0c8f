#include "app/render_to_file.h"

#include "render/session/render_session.h"
#include "scene/image_io.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>

namespace wavelit::editor {

struct RenderToFile::Shared {
    std::atomic<bool> cancel{false};
};

QString checkRenderTarget(const QString& path, const RenderBudget& budget) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != "exr" && suffix != "png")
        return QStringLiteral("'%1': render to file writes .exr (linear) or .png (sRGB), not '.%2'")
            .arg(QDir::toNativeSeparators(path), suffix);
    if ((budget.samplesPerPixel > 0) == (budget.seconds > 0.0))
        return QStringLiteral("render to file needs a budget of samples per pixel or of seconds (one of them, positive)");
    return {};
}

RenderToFile::RenderToFile(QObject* parent) : QObject(parent), m_shared(std::make_shared<Shared>()) {}

RenderToFile::~RenderToFile() {
    if (m_watcher) {
        m_shared->cancel = true;
        m_watcher->waitForFinished();
    }
}

void RenderToFile::cancel() { m_shared->cancel = true; }

bool RenderToFile::start(std::shared_ptr<const scene::Scene> scene, const render::RenderOptions& options,
                         RenderBudget budget, const QString& path, float exposureEv, QString* error) {
    if (m_watcher) return *error = tr("A render to file is already running."), false;
    if (!scene) return *error = tr("No scene is open."), false;
    if (QString problem = checkRenderTarget(path, budget); !problem.isEmpty()) return *error = problem, false;
    m_shared = std::make_shared<Shared>();
    m_path = path;
    m_watcher = new QFutureWatcher<QString>(this);
    connect(m_watcher, &QFutureWatcherBase::finished, this, [this] {
        const QString result = m_watcher->result();
        m_watcher->deleteLater();
        m_watcher = nullptr;
        emit finished(m_path, result);
    });
    QPointer<RenderToFile> self(this);
    auto report = [self](double fraction, QString text) {
        QMetaObject::invokeMethod(self.data(), [self, fraction, text] {
            if (self) emit self->progress(fraction, text);
        }, Qt::QueuedConnection);
    };
    std::shared_ptr<Shared> shared = m_shared;
    m_watcher->setFuture(QtConcurrent::run([=]() -> QString {
        auto created = render::RenderSession::create(*scene, options);
        if (!created) return QString::fromStdString(created.error().message());
        std::unique_ptr<render::RenderSession> session = std::move(created.value());
        session->setInterruptCheck([shared] { return shared->cancel.load(); });
        QElapsedTimer clock;
        clock.start();
        auto done = [&] {
            return budget.samplesPerPixel > 0 ? session->samplesPerPixel() >= budget.samplesPerPixel
                                              : clock.elapsed() >= qint64(budget.seconds * 1000.0);
        };
        while (session->samplesPerPixel() == 0 || !done()) { // at least one pass
            if (shared->cancel) return QStringLiteral("cancelled");
            if (auto status = session->renderPass(); !status)
                return QString::fromStdString(status.error().message());
            const int spp = session->samplesPerPixel();
            const double seconds = double(clock.elapsed()) / 1000.0;
            const double fraction = budget.samplesPerPixel > 0 ? double(spp) / budget.samplesPerPixel
                                                               : seconds / budget.seconds;
            report(std::min(fraction, 1.0), QStringLiteral("%1 spp · %2 s").arg(spp).arg(seconds, 0, 'f', 1));
        }
        if (shared->cancel) return QStringLiteral("cancelled");
        auto image = session->image();
        if (!image) return QString::fromStdString(image.error().message());
        auto status = scene::writeImage(path.toStdString(), *image, exposureEv);
        return status ? QString() : QString::fromStdString(status.error().message());
    }));
    return true;
}

} // namespace wavelit::editor
