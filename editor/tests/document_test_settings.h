// Settings for editor tests about documents (saving, undo, recovery), not images: a 32x32 render
// with the cheapest sampler, one sample per pixel, so the render thread costs next to nothing.
#pragma once

#include "viewport/render_controller.h"

namespace wavelit::editor {

inline constexpr int kDocumentTimeoutMs = 60000;

inline RenderSettings documentTestSettings() {
    RenderSettings settings;
    settings.width = 32;
    settings.height = 32;
    settings.sampler = render::SamplerKind::Bsdf;
    settings.maxSamplesPerPixel = 1;
    return settings;
}

} // namespace wavelit::editor
