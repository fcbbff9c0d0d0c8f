// ViewportWidget: paints the latest render frame's display image (tone-mapped on the render
// thread, RenderFrame::display), scaled to fit with its aspect ratio kept. Exposure is display
// state: setExposure emits exposureChanged, which MainWindow connects to
// RenderController::setExposure; the render thread re-maps the frame it holds and re-delivers it,
// the render never restarts and the UI thread never tone-maps a large image.
// Interaction handlers are one event-filter class each in viewport/ (camera_orbit_handler.h,
// viewport_interaction.h); the widget maps between its own and the image's pixel coordinates and
// draws their overlay: a handle per light and the selection's move gizmo (move_gizmo.h).
#pragma once

#include "panels/entity_ref.h"
#include "viewport/gizmo_mode.h"
#include "viewport/render_frame.h"

#include <QElapsedTimer>
#include <QImage>
#include <QTimer>
#include <QWidget>

#include <algorithm>
#include <memory>
#include <optional>

namespace wavelit::editor {

inline constexpr int kCrossFadeMs = 200;

class ViewportWidget : public QWidget {
    Q_OBJECT
public:
    explicit ViewportWidget(QWidget* parent = nullptr);

    void showFrame(const RenderFrame& frame);
    void clear();
    void setExposure(float ev);
    float exposure() const { return m_exposureEv; }

    const QImage& displayedImage() const { return m_display; }
    // The exposure the displayed image was mapped with (lags exposure() until the re-mapped
    // frame arrives).
    float displayedExposure() const { return m_frame.displayExposureEv; }
    int displayedSamplesPerPixel() const { return m_frame.samplesPerPixel; }

    QSize sizeHint() const override { return {640, 480}; }

    // The displayed image's size in its own pixels (empty before the first frame), where it sits
    // in the widget, and the mapping between widget and image points (nullopt outside the image).
    QSize imageSize() const { return m_display.size(); }
    QRectF imageRect() const;
    std::optional<QPointF> widgetToImage(QPointF widgetPoint) const;
    QPointF imageToWidget(QPointF imagePoint) const;
    // Image pixels per screen pixel (the image is scaled to fit); 1 before the first frame.
    float imagePixelsPerScreenPixel() const;
    // What the overlay draws: the scene's light handles and the selection's gizmo.
    void setOverlay(std::shared_ptr<const scene::Scene> scene, std::optional<EntityRef> selection);
    void setGizmoMode(GizmoMode mode);
    GizmoMode gizmoMode() const { return m_gizmoMode; }
    // A refusal drawn beside the selection ("" hides it): a clamped manipulator drag.
    void setOverlayMessage(const QString& message);
    const QString& overlayMessage() const { return m_overlayMessage; }

    // Cross-fade (see the class comment). 0 switches at once.
    void setCrossFadeMs(int ms) { m_fadeMs = std::max(ms, 0); }
    int crossFadeMs() const { return m_fadeMs; }
    // The opacity of the new image in the latest paint: in (0, 1) while a fade was painted, -1
    // when the latest paint showed one image.
    double lastPaintedFade() const { return m_lastPaintedFade; }
    bool fading() const { return !m_fadeFrom.isNull(); }

signals:
    void exposureChanged(float ev);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    void paintOverlay(QPainter& painter) const;
    void stopFade();
    RenderFrame m_frame;
    GizmoMode m_gizmoMode = GizmoMode::Move;
    QString m_overlayMessage;
    QImage m_fadeFrom; // the preview being faded out; null when not fading
    QElapsedTimer m_fadeClock;
    QTimer m_fadeTimer;
    int m_fadeMs = kCrossFadeMs;
    double m_lastPaintedFade = -1.0;
    std::shared_ptr<const scene::Scene> m_overlayScene;
    std::optional<EntityRef> m_selection;
    QImage m_display;
    float m_exposureEv = 0.0f;
};

} // namespace wavelit::editor
