// ViewportWidget: paints the latest render frame, tone-mapped on the UI thread from the linear
// image (tone_map.h), scaled to fit with its aspect ratio kept. Exposure is display state: a new
// exposure re-maps the frame already held and never restarts the render.
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
    int displayedSamplesPerPixel() const { return m_frame.samplesPerPixel; }

    QSize sizeHint() const override { return {640, 480}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    RenderFrame m_frame;
    QImage m_display;
    float m_exposureEv = 0.0f;
};

} // namespace wavelit::editor
