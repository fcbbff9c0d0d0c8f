// AppApi's viewport calls (docs/scripting.md "Viewport", issue 14): drags and clicks as real mouse
// events sent to the viewport widget, so they go through the same event filters (camera,
// picking, gizmos) as the mouse; the displayed frame's kind and latency; undo and redo; and the
// pixels a test compares. Image points are in the viewport image's pixels ((0, 0) its top-left
// corner, the render size), mapped to the widget as it is laid out.
#include "scripting/script_api.h"

#include "app/error_reporter.h"
#include "app/main_window.h"
#include "app/scene_document.h"
#include "panels/entity_ref.h"
#include "panels/outline_panel.h"
#include "viewport/render_controller.h"
#include "viewport/scene_picker.h"
#include "viewport/view_projection.h"
#include "viewport/viewport_widget.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QJSEngine>
#include <QMouseEvent>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>

namespace wavelit::editor {
namespace {

// Lets queued events (edits, frames) run for `ms` (at least one pass of the event loop).
void spin(int ms) {
    QEventLoop loop;
    QTimer::singleShot(std::max(ms, 0), &loop, &QEventLoop::quit);
    loop.exec(QEventLoop::AllEvents);
}

struct DragInput {
    Qt::MouseButton button = Qt::LeftButton;
    Qt::KeyboardModifiers modifiers = Qt::NoModifier;
};

std::optional<DragInput> parseModifiers(const QString& text) {
    DragInput input;
    for (const QString& part : text.toLower().split('+', Qt::SkipEmptyParts)) {
        const QString p = part.trimmed();
        if (p == "ctrl" || p == "control") input.modifiers |= Qt::ControlModifier;
        else if (p == "shift") input.modifiers |= Qt::ShiftModifier;
        else if (p == "alt") input.modifiers |= Qt::AltModifier;
        else if (p == "middle") input.button = Qt::MiddleButton;
        else if (p == "right") input.button = Qt::RightButton;
        else return std::nullopt;
    }
    return input;
}

void sendMouse(QWidget* widget, QEvent::Type type, QPointF at, Qt::MouseButton button,
               Qt::MouseButtons buttons, Qt::KeyboardModifiers modifiers) {
    QMouseEvent event(type, at, widget->mapToGlobal(at), button, buttons, modifiers);
    QCoreApplication::sendEvent(widget, &event);
}

QString frameKindName(RenderFrame::Kind kind) {
    return kind == RenderFrame::Kind::PathTraced ? QStringLiteral("pathtraced") : QStringLiteral("preview");
}

QString frameSourceName(RenderFrame::Kind kind) {
    switch (kind) {
    case RenderFrame::Kind::PathTraced: return QStringLiteral("pathtraced");
    case RenderFrame::Kind::Draft: return QStringLiteral("draft");
    case RenderFrame::Kind::Relight: return QStringLiteral("relight");
    }
    return {};
}

} // namespace

bool AppApi::dragInViewport(double x0, double y0, double x1, double y1, const QString& modifiers, int steps,
                            int msPerStep) {
    ViewportWidget* viewport = m_window->viewport();
    if (viewport->imageSize().isEmpty()) return fail("dragInViewport: the viewport shows no image yet");
    const auto input = parseModifiers(modifiers);
    if (!input)
        return fail(QStringLiteral("dragInViewport: modifiers are '+'-joined ctrl, shift, alt, middle, "
                                   "right; got \"%1\"").arg(modifiers));
    if (steps < 1) return fail(QStringLiteral("dragInViewport: steps must be >= 1, got %1").arg(steps));
    const QPointF from = viewport->imageToWidget({x0, y0});
    const QPointF to = viewport->imageToWidget({x1, y1});
    if (!viewport->widgetToImage(from))
        return fail(QStringLiteral("dragInViewport: (%1, %2) is outside the %3x%4 viewport image")
                        .arg(x0).arg(y0).arg(viewport->imageSize().width()).arg(viewport->imageSize().height()));
    sendMouse(viewport, QEvent::MouseButtonPress, from, input->button, input->button, input->modifiers);
    for (int i = 1; i <= steps; ++i) {
        const double t = double(i) / double(steps);
        sendMouse(viewport, QEvent::MouseMove, from + (to - from) * t, Qt::NoButton, input->button,
                  input->modifiers);
        spin(msPerStep);
    }
    sendMouse(viewport, QEvent::MouseButtonRelease, to, input->button, Qt::NoButton, input->modifiers);
    spin(0);
    return true;
}

QString AppApi::pickInViewport(double x, double y) {
    ViewportWidget* viewport = m_window->viewport();
    if (viewport->imageSize().isEmpty()) return fail("pickInViewport: the viewport shows no image yet"), QString();
    const QPointF at = viewport->imageToWidget({x, y});
    if (!viewport->widgetToImage(at))
        return fail(QStringLiteral("pickInViewport: (%1, %2) is outside the viewport image").arg(x).arg(y)),
               QString();
    // A click: press and release without motion (viewport_interaction.h).
    sendMouse(viewport, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    sendMouse(viewport, QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
    spin(0);
    auto scene = m_window->document()->scene();
    const auto selected = m_window->outline()->selectedEntity();
    if (!scene || !selected) return QString();
    return QString::fromStdString(qualifiedName(*scene, *selected));
}

QJSValue AppApi::handleInViewport(const QString& entity) {
    auto scene = m_window->document()->scene();
    if (!scene) return fail("handleInViewport: no scene is open"), QJSValue();
    auto ref = resolveEntity(*scene, entity.toStdString());
    if (!ref) return fail("handleInViewport: " + QString::fromStdString(ref.error().message())), QJSValue();
    const QSize size = m_window->viewport()->imageSize();
    if (size.isEmpty()) return fail("handleInViewport: the viewport shows no image yet"), QJSValue();
    const auto world = handlePosition(*scene, *ref);
    if (!world) return QJSValue(QJSValue::NullValue);
    const auto p = ViewProjection(scene->camera, size.width(), size.height()).project(*world);
    if (!p) return QJSValue(QJSValue::NullValue);
    QJSValue out = m_engine->newArray(2);
    out.setProperty(quint32(0), double(p->x));
    out.setProperty(quint32(1), double(p->y));
    return out;
}

QJSValue AppApi::waitForFrame(double timeoutSeconds) {
    RenderController* render = m_window->renderer();
    QString error;
    QMetaObject::Connection failed = connect(m_window->errors(), &ErrorReporter::reported, this,
                                             [&](const QString& message) { error = message; });
    QDeadlineTimer deadline(qint64(timeoutSeconds * 1000.0));
    while (error.isEmpty() && !render->displayedIsCurrent() && !deadline.hasExpired()) spin(1);
    disconnect(failed);
    if (!error.isEmpty()) return fail(error), QJSValue();
    if (!render->displayedIsCurrent())
        return fail(QStringLiteral("waitForFrame: no frame of the latest edit after %1 s").arg(timeoutSeconds)),
               QJSValue();
    const RenderFrame& frame = render->displayedFrame();
    QJSValue out = m_engine->newObject();
    out.setProperty("spp", frame.samplesPerPixel);
    out.setProperty("kind", frameKindName(frame.kind));
    out.setProperty("source", frameSourceName(frame.kind));
    out.setProperty("approximate", frame.approximate);
    out.setProperty("msSinceEdit", frame.msSinceEdit);
    out.setProperty("estimatedRelError", frame.estimatedRelError);
    return out;
}

QJSValue AppApi::frameLuminance(const QString& which) {
    RenderController* render = m_window->renderer();
    const RenderFrame* frame = nullptr;
    if (which.isEmpty() || which == "pathtraced") frame = &render->latestFrame();
    else if (which == "displayed") frame = &render->displayedFrame();
    else
        return fail(QStringLiteral("frameLuminance: expected \"pathtraced\" or \"displayed\", not \"%1\"").arg(which)),
               QJSValue();
    if (!frame->image) return fail("frameLuminance: no such frame yet"), QJSValue();
    const util::ImageRGB& image = *frame->image;
    QJSValue out = m_engine->newArray(quint32(image.pixels.size()));
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const glm::vec3& c = image.pixels[i]; // Rec.709 luminance (architecture.md §6)
        out.setProperty(quint32(i), 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b);
    }
    return out;
}

void AppApi::processEvents(int ms) { spin(ms); }

int AppApi::framesShown() const { return m_window->renderer()->framesDisplayed(); }

} // namespace wavelit::editor
