// What a render side of the A/B view (app/lightmix_compare.h) renders with: the options the
// viewport's render thread would use for that scene (RenderController::submit: the settings'
// size or the scene's render defaults, its bounces, the settings' sampler, device and
// validation), its samples-per-pixel limit, and the file relative asset paths start from. So at
// equal samples a render side is the image the viewport would show for that setup.
#pragma once

#include "app/lightmix_compare.h"
#include "viewport/render_controller.h"

#include <QString>

namespace wavelit::editor {

render::RenderOptions viewportRenderOptions(const RenderSettings& settings, const scene::Scene& scene);
LightMixCompare::RenderContext compareRenderContext(const RenderController& renderer, const QString& scenePath);

} // namespace wavelit::editor
