#include "lightmix/compare_render_context.h"

namespace wavelit::editor {

render::RenderOptions viewportRenderOptions(const RenderSettings& settings, const scene::Scene& scene) {
    render::RenderOptions options;
    options.width = settings.width > 0 ? settings.width : scene.render.width;
    options.height = settings.height > 0 ? settings.height : scene.render.height;
    options.bounces = scene.render.bounces;
    options.device = settings.device;
    options.sampler = settings.sampler;
    options.validation = settings.validation;
    options.lightGroups = false;
    return options;
}

LightMixCompare::RenderContext compareRenderContext(const RenderController& renderer, const QString& scenePath) {
    const RenderSettings settings = renderer.settings();
    return {[settings](const scene::Scene& scene) { return viewportRenderOptions(settings, scene); },
            settings.maxSamplesPerPixel, scenePath.toStdString()};
}

} // namespace wavelit::editor
