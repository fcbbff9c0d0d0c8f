#include "relight/relight_preview.h"

#include "relight/camera_lights.h"
#include "relight/light_projection.h"
#include "util/parallel_for.h"

namespace wavelit::relight {

RelightPreview::RelightPreview(const RelightSettings& settings)
    : m_settings(settings), m_dirs(settings.level) {}

util::Result<std::unique_ptr<RelightPreview>> RelightPreview::create(const scene::Scene& scene,
                                                                    const RelightSettings& settings) {
    auto bad = [](const std::string& why) {
        return util::makeError(util::ErrorKind::Invalid, "", "relight settings: " + why);
    };
    if (settings.level < 1 || settings.level > 7) return bad("sphere level must be in 1..7");
    if (settings.width < 1 || settings.height < 1 || settings.width > 4096 || settings.height > 4096)
        return bad("preview size must be in 1..4096");
    if (settings.keep < 1) return bad("keep at least 1 coefficient");
    std::unique_ptr<RelightPreview> preview(new RelightPreview(settings));
    preview->rebuildAll(scene);
    return preview;
}

void RelightPreview::resolveMaterials() {
    // The lights at unit power, once per scene (not per pixel: a copy holds the light's name).
    m_unitLights.clear();
    for (const scene::Light& light : m_scene->lighting.lights) m_unitLights.push_back(unitPowerLight(light));
    m_materials.clear();
    auto resolve = [&](const scene::Material& m) { return resolveMaterial(m, m_dirs.texelRadius()); };
    for (const scene::Material& m : m_scene->materials) m_materials.push_back(resolve(m));
    m_materials.push_back(resolve(scene::Material{})); // index == size: the default material
}

TransferContext RelightPreview::context() const {
    TransferContext ctx;
    ctx.scene = m_scene.get();
    ctx.dirs = &m_dirs;
    ctx.occluders = &m_occluders;
    ctx.sceneBvh = &m_bvh;
    ctx.materials = &m_materials;
    ctx.environment = &m_environment;
    ctx.keep = m_settings.keep;
    return ctx;
}

void RelightPreview::rebuildAll(const scene::Scene& scene) {
    m_scene = std::make_unique<scene::Scene>(scene);
    resolveMaterials();
    m_bvh = scene::buildBvh(*m_scene);
    m_occluders.clear();
    for (size_t j = 0; j < m_scene->objects.size(); ++j)
        m_occluders.push_back(buildObjectOccluder(*m_scene, j, m_convexity));
    buildEnvironment();
    m_points = castPreviewPoints(*m_scene, m_bvh, m_settings.width, m_settings.height, m_settings.threads);
    m_states.assign(m_points.size(), PointState{});
    m_deferred.assign(m_points.size(), 0);
    m_background.assign(m_points.size(), glm::vec3(0.0f));
    m_cameraLights.assign(m_scene->lighting.lights.size(), std::vector<glm::vec3>(m_points.size()));
    const TransferContext ctx = context();
    const CameraRays rays(m_scene->camera, m_settings.width, m_settings.height);
    util::parallelFor(m_points.size(), m_settings.threads, [&](size_t i) {
        for (size_t k = 0; k < m_cameraLights.size(); ++k) updateCameraLight(k, i, rays);
        if (m_points[i].hit) m_states[i] = buildPointState(ctx, m_points[i]);
        else m_background[i] = environmentRadiance(m_scene->lighting.environment, -m_points[i].wo);
    });
}

void RelightPreview::buildEnvironment() {
    const scene::Environment& env = m_scene->lighting.environment;
    const util::ImageRGB* image = env.image && !env.image->empty() ? env.image.get() : nullptr;
    if (image != m_envSourceOf || !m_envSource) {
        m_envSource = image ? reduceEquirect(*image, m_settings.level) : nullptr;
        m_envSourceOf = image;
    }
    m_environment = buildEnvironmentFactor(env, m_settings.level, m_envSource.get());
}

void RelightPreview::updateCameraLight(size_t k, size_t i, const CameraRays& rays) {
    const int w = m_settings.width;
    m_cameraLights[k][i] = lightSeenByPixel(m_unitLights[k], m_scene->camera, rays,
                                            int(i % size_t(w)), int(i / size_t(w)), m_points[i].distance);
}

glm::vec3 RelightPreview::radiance(size_t i, const std::vector<glm::vec3>& powers) const {
    glm::vec3 lights(0.0f);
    for (size_t k = 0; k < m_cameraLights.size(); ++k)
        lights += m_cameraLights[k][i] * powers[k];
    const glm::vec3 envScale = environmentScale(m_scene->lighting.environment);
    if (!m_points[i].hit) return m_background[i] * envScale + lights;
    const ResolvedMaterial& m = m_materials[std::min<size_t>(m_points[i].material, m_materials.size() - 1)];
    return lights + m.emission + mixTerms(m, m_states[i], envScale, powers);
}

util::ImageRGB RelightPreview::image() const {
    util::ImageRGB out(m_settings.width, m_settings.height);
    std::vector<glm::vec3> powers;
    for (const scene::Light& light : m_scene->lighting.lights) powers.push_back(lightPower(light));
    for (size_t i = 0; i < m_points.size(); ++i) out.pixels[i] = radiance(i, powers);
    return out;
}

util::ImageRGB RelightPreview::image(int width, int height) const {
    const util::ImageRGB small = image();
    if (width == small.width && height == small.height) return small;
    util::ImageRGB out(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int sx = std::min(small.width - 1, int(int64_t(x) * small.width / width));
            const int sy = std::min(small.height - 1, int(int64_t(y) * small.height / height));
            out.at(x, y) = small.at(sx, sy);
        }
    return out;
}

size_t RelightPreview::hitCount() const {
    size_t n = 0;
    for (const PreviewPoint& p : m_points) n += p.hit ? 1 : 0;
    return n;
}

size_t RelightPreview::stateBytes() const {
    size_t b = 0;
    for (size_t i = 0; i < m_points.size(); ++i)
        if (m_points[i].hit) b += m_states[i].bytes();
    return b;
}

} // namespace wavelit::relight
