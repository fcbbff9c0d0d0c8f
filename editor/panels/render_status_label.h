// RenderStatusLabel: the status bar's permanent render readout,
//   "12 spp · 3.4 s · 0.9 Msamples/s · wavelet · noise ≈ 4.1% · llvmpipe — uploaded: lights"
// samples per pixel, render time since the last restart, samples (paths) per second, the
// direction sampler, the estimated relative RMS noise of the image (panels/noise_estimate.h:
// from two frames with disjoint samples; shown once one exists), the device, for a relighting
// preview whether it is the approximate first answer of a drag or the exact preview, and what
// the last scene update rebuilt and uploaded (RenderFrame::lastUpdate).
#pragma once

#include "panels/noise_estimate.h"
#include "viewport/render_frame.h"

#include <QLabel>

#include <optional>

namespace wavelit::editor {

class RenderStatusLabel : public QLabel {
    Q_OBJECT
public:
    explicit RenderStatusLabel(QWidget* parent = nullptr);
    void showFrame(const RenderFrame& frame);
    void showState(const QString& text); // "loading…", "render failed"
    void setSampler(const QString& name) { m_sampler = name; }
    // The estimate shown with the latest frame (relative RMS noise), if any.
    std::optional<double> noise() const { return m_noise; }

    static QString format(const RenderFrame& frame, const QString& sampler = {},
                          std::optional<double> noise = std::nullopt);

private:
    QString m_sampler;
    NoiseEstimator m_estimator;
    std::optional<double> m_noise;
};

} // namespace wavelit::editor
