// The `app` calls of issue 14 (docs/scripting.md "Files, outline and panels"): outline edits,
// undo/redo, lighting setups, environment maps, drops, render to file, the status line.
#include "scripting/script_api.h"

#include "app/error_reporter.h"
#include "app/file_actions.h"
#include "app/main_window.h"
#include "app/outline_actions.h"
#include "app/recent_files.h"
#include "app/scene_document.h"
#include "viewport/render_controller.h"
#include "panels/entity_ref.h"
#include "panels/outline_panel.h"
#include "panels/render_status_label.h"

#include "scene/image_io.h"

#include <glm/vec3.hpp>

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDropEvent>
#include <QEventLoop>
#include <QFileInfo>
#include <QImage>
#include <QJSEngine>
#include <QMimeData>
#include <QTimer>
#include <QUndoStack>
#include <QUrl>

#include <cmath>

namespace wavelit::editor {
namespace {

template <typename Done> void spinUntil(Done done) {
    while (!done()) {
        QEventLoop loop;
        QTimer::singleShot(10, &loop, &QEventLoop::quit);
        loop.exec(QEventLoop::AllEvents);
    }
}

QString toQ(const util::Error& error) { return QString::fromStdString(error.message()); }

} // namespace

bool AppApi::waitForFileOperation(const std::function<void(std::function<void(const QString&)>)>& start) {
    bool done = false;
    QString error;
    start([&done, &error](const QString& e) {
        error = e;
        done = true;
    });
    spinUntil([&] { return done; });
    return error.isEmpty();
}

QString AppApi::addLight(const QString& type, const QString& name) {
    auto added = m_window->outlineActions()->addLight(type, name);
    if (!added) return fail("addLight: " + toQ(added.error())), QString();
    return QString::fromStdString(entityName(*m_window->document()->scene(), *added));
}

QJSValue AppApi::addObject(const QString& meshPath, const QString& name) {
    if (!waitForFileOperation([&](auto done) { m_window->files()->addObject(meshPath, name, done); }))
        return QJSValue(false);
    auto selected = m_window->outline()->selectedEntity();
    return selected ? QJSValue(QString::fromStdString(entityName(*m_window->document()->scene(), *selected)))
                    : QJSValue(true);
}

QString AppApi::addMaterial(const QString& name) {
    auto added = m_window->outlineActions()->addMaterial(name);
    if (!added) return fail("addMaterial: " + toQ(added.error())), QString();
    return QString::fromStdString(entityName(*m_window->document()->scene(), *added));
}

bool AppApi::remove(const QString& entity) {
    auto scene = m_window->document()->scene();
    if (!scene) return fail("remove: no scene is open");
    auto ref = resolveEntity(*scene, entity.toStdString());
    if (!ref) return fail("remove: " + toQ(ref.error()));
    auto status = m_window->outlineActions()->remove(*ref);
    return status ? true : fail("remove: " + toQ(status.error()));
}

QString AppApi::duplicate(const QString& entity) {
    auto scene = m_window->document()->scene();
    if (!scene) return fail("duplicate: no scene is open"), QString();
    auto ref = resolveEntity(*scene, entity.toStdString());
    if (!ref) return fail("duplicate: " + toQ(ref.error())), QString();
    auto added = m_window->outlineActions()->duplicate(*ref);
    if (!added) return fail("duplicate: " + toQ(added.error())), QString();
    return QString::fromStdString(entityName(*m_window->document()->scene(), *added));
}

bool AppApi::rename(const QString& entity, const QString& name) {
    auto scene = m_window->document()->scene();
    if (!scene) return fail("rename: no scene is open");
    auto ref = resolveEntity(*scene, entity.toStdString());
    if (!ref) return fail("rename: " + toQ(ref.error()));
    auto status = m_window->outlineActions()->rename(*ref, name);
    return status ? true : fail("rename: " + toQ(status.error()));
}

bool AppApi::undo() {
    QUndoStack* stack = m_window->document()->undoStack();
    if (!stack->canUndo()) return false;
    stack->undo();
    return true;
}

bool AppApi::redo() {
    QUndoStack* stack = m_window->document()->undoStack();
    if (!stack->canRedo()) return false;
    stack->redo();
    return true;
}

bool AppApi::newScene() {
    m_window->files()->newScene();
    return true;
}

bool AppApi::saveLighting(const QString& path) {
    return waitForFileOperation([&](auto done) { m_window->files()->saveLighting(path, done); });
}

bool AppApi::applyLighting(const QString& path) {
    return waitForFileOperation([&](auto done) { m_window->files()->applyLighting(path, done); });
}

bool AppApi::setEnvironmentMap(const QString& path) {
    return waitForFileOperation([&](auto done) { m_window->files()->setEnvironmentMap(path, done); });
}

bool AppApi::dropFile(const QString& path) {
    // The events a file manager's drag delivers: enter (refused for a type nobody takes), drop.
    auto* mime = new QMimeData;
    mime->setUrls({QUrl::fromLocalFile(QFileInfo(path).absoluteFilePath())});
    const QPoint centre = m_window->rect().center();
    QDragEnterEvent enter(centre, Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(m_window, &enter);
    if (!enter.isAccepted()) {
        delete mime;
        return fail(QStringLiteral("dropFile: the window does not take '%1'").arg(path));
    }
    const int failuresBefore = m_window->files()->failures();
    QDropEvent drop(QPointF(centre), Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(m_window, &drop);
    delete mime;
    SceneDocument* document = m_window->document();
    spinUntil([&] { return m_window->files()->pendingDrops() == 0 && !document->isLoading(); });
    return m_window->files()->failures() == failuresBefore;
}

bool AppApi::renderToFile(const QString& path, const QJSValue& budget) {
    RenderBudget b;
    if (budget.hasProperty("spp")) b.samplesPerPixel = budget.property("spp").toInt();
    if (budget.hasProperty("seconds")) b.seconds = budget.property("seconds").toNumber();
    return waitForFileOperation([&](auto done) { m_window->files()->renderToFile(path, b, false, done); });
}

QString AppApi::lastError() const { return m_window->files()->lastError(); }

QStringList AppApi::recentFiles() const { return m_window->files()->recent()->files(); }

QString AppApi::statusText() const { return m_window->statusLabel()->text(); }

int AppApi::validationMessages() const { return m_window->renderer()->latestFrame().validationMessages; }

double AppApi::noiseEstimate() const { return m_window->statusLabel()->noise().value_or(-1.0); }

QJSValue AppApi::imageInfo(const QString& path) {
    if (QFileInfo(path).suffix().toLower() == "png") { // display output: 8-bit, read by Qt
        const QImage png(path);
        if (png.isNull()) return fail(QStringLiteral("imageInfo: '%1' is not a readable PNG").arg(path)), QJSValue();
        QJSValue out = m_engine->newObject();
        out.setProperty("width", png.width());
        out.setProperty("height", png.height());
        out.setProperty("finite", true);
        return out;
    }
    // Unsanitised: a NaN or Inf texel is an error of loadImage, reported here as finite = false.
    scene::ImageLoadOptions strict;
    strict.sanitize = false;
    auto loaded = scene::loadImage(path.toStdString(), strict);
    bool finite = true;
    if (!loaded) {
        loaded = scene::loadImage(path.toStdString());
        if (!loaded) return fail("imageInfo: " + toQ(loaded.error())), QJSValue();
        finite = false;
    }
    const util::ImageRGB& image = loaded->image;
    glm::dvec3 sum(0.0);
    for (const glm::vec3& p : image.pixels) sum += glm::dvec3(p);
    const glm::dvec3 mean = image.empty() ? sum : sum / double(image.pixels.size());
    QJSValue out = m_engine->newObject();
    out.setProperty("width", image.width);
    out.setProperty("height", image.height);
    out.setProperty("finite", finite);
    QJSValue m = m_engine->newArray(3);
    for (int i = 0; i < 3; ++i) m.setProperty(quint32(i), mean[i]);
    out.setProperty("mean", m);
    out.setProperty("meanLuminance", 0.2126 * mean.r + 0.7152 * mean.g + 0.0722 * mean.b);
    return out;
}

QJSValue AppApi::compareImages(const QString& a, const QString& b) {
    auto ia = scene::loadImage(a.toStdString());
    if (!ia) return fail("compareImages: " + toQ(ia.error())), QJSValue();
    auto ib = scene::loadImage(b.toStdString());
    if (!ib) return fail("compareImages: " + toQ(ib.error())), QJSValue();
    const util::ImageRGB& x = ia->image;
    const util::ImageRGB& y = ib->image;
    if (x.width != y.width || x.height != y.height || x.empty())
        return fail(QStringLiteral("compareImages: '%1' is %2x%3, '%4' is %5x%6")
                        .arg(a).arg(x.width).arg(x.height).arg(b).arg(y.width).arg(y.height)),
               QJSValue();
    double squares = 0.0, sumA = 0.0, sumB = 0.0;
    for (size_t i = 0; i < x.pixels.size(); ++i) {
        const double la = util::luminance(x.pixels[i]), lb = util::luminance(y.pixels[i]);
        squares += (la - lb) * (la - lb);
        sumA += la;
        sumB += lb;
    }
    const double n = double(x.pixels.size());
    QJSValue out = m_engine->newObject();
    out.setProperty("rms", std::sqrt(squares / n));
    out.setProperty("relativeRms", sumA + sumB > 0.0 ? std::sqrt(squares / n) / ((sumA + sumB) / (2.0 * n)) : 0.0);
    out.setProperty("meanA", sumA / n);
    out.setProperty("meanB", sumB / n);
    return out;
}

} // namespace wavelit::editor
