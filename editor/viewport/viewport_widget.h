// ViewportWidget: paints the latest render frame's display image (tone-mapped on the render
// thread, RenderFrame::display), scaled to fit with its aspect ratio kept. Exposure is display
// state: setExposure emits exposureChanged, which MainWindow connects to
// RenderController::setExposure; the render thread re-maps the frame it holds and re-delivers it,
// the render never restarts and the UI thread never tone-maps a large image.
// Interaction handlers (camera orbit, picking) will be one event-filter class each in viewport/.
#pragma once

#include "viewport/render_frame.h"

#include <QImage>
#include <QWidget>

namespace wavelit::editor {

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

signals:
    void exposureChanged(float ev);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    RenderFrame m_frame;
    QImage m_display;
    float m_exposureEv = 0.0f;
};

} // namespace wavelit::editor
