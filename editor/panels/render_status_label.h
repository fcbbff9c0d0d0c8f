// RenderStatusLabel: the status bar's permanent render readout, "12 spp · 3.4 s · llvmpipe", then
// what the last scene update rebuilt and uploaded ("— uploaded: lights", RenderFrame::lastUpdate).
#pragma once

#include "viewport/render_frame.h"

#include <QLabel>

namespace wavelit::editor {

class RenderStatusLabel : public QLabel {
    Q_OBJECT
public:
    explicit RenderStatusLabel(QWidget* parent = nullptr);
    void showFrame(const RenderFrame& frame);
    void showState(const QString& text); // "loading…", "render failed"

    static QString format(const RenderFrame& frame);
};

} // namespace wavelit::editor
