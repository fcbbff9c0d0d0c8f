#include "render/gpu/gpu_scene_data.h"

#include "render/lights/light_sampler.h"
#include "plugins/brdf.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace wavelit::render {
namespace {

constexpr float kPi = 3.14159265358979323846f;

void set4(float* dst, const glm::vec3& v, float w) {
    dst[0] = v.x;
    dst[1] = v.y;
    dst[2] = v.z;
    dst[3] = w;
}

util::Result<GpuMaterial> packMaterial(const scene::Material& m, size_t index,
                                       const GpuBrdfTables& tables) {
    GpuMaterial g{};
    const plugins::Brdf* brdf = plugins::findBrdf(m.brdf);
    if (!brdf || !plugins::brdfGpuTwinProblem(*brdf).empty())
        return util::makeError(util::ErrorKind::Unsupported, "",
                               "material '" + m.name + "' uses BRDF '" + m.brdf +
                                   "', which has no GLSL twin: the Vulkan tracer cannot render it, "
                                   "the CPU tracer can",
                               "/materials/" + std::to_string(index) + "/brdf");
    const uint32_t type = gpuBrdfType(*brdf, scene::brdfParamsOf(m));
    // A plugin that reads a table (`measured`, no roughness) gets its table's offset in the
    // roughness slot (gpu_brdf_tables.h); packGpuBrdfTables has seen every material's table.
    const float roughnessSlot =
        plugins::brdfReadsFile(*brdf) ? float(tables.offsetOf.at(m.brdfTable.get())) : m.roughness;
    set4(g.baseColorRoughness, m.baseColor, roughnessSlot);
    set4(g.emissionType, m.emission, float(type));
    return g;
}

} // namespace

uint32_t gpuBrdfType(const plugins::Brdf& brdf) { return uint32_t(plugins::brdfIndex(brdf)); }

uint32_t gpuBrdfType(const plugins::Brdf& brdf, const plugins::BrdfParams& params) {
    const plugins::BrdfGpuTwin twin = brdf.gpuTwin();
    const float step = twin.typeParameter ? plugins::brdfTypeParameterStep(twin.typeParameter(params)) : 0.0f;
    return gpuBrdfType(brdf) +
           plugins::kBrdfTypeCodePlugins * uint32_t(step * float(plugins::kBrdfTypeParameterSteps));
}

GpuLight packGpuLight(const scene::Light& light) {
    // The constants LightSampler uses on the CPU, so both tracers see the same values.
    const LightConstants c = deriveLightConstants(light);
    uint32_t type = kGpuLightPoint;
    switch (c.type) {
    case scene::LightType::Point: type = kGpuLightPoint; break;
    case scene::LightType::Sphere: type = kGpuLightSphere; break;
    case scene::LightType::Spot: type = kGpuLightSpot; break;
    case scene::LightType::Rect: type = kGpuLightRect; break;
    case scene::LightType::Sun: type = kGpuLightSun; break;
    }
    GpuLight g{};
    set4(g.positionType, c.position, float(type));
    set4(g.normalRadius, c.normal, c.radius);
    set4(g.emissionArea, c.emission, c.area);
    set4(g.axisUInner, c.axisU, c.cosInner);
    set4(g.axisVOuter, c.axisV, c.cosOuter);
    g.sun[0] = c.sin2Sun;
    g.sun[1] = c.oneMinusCosSun;
    g.sun[2] = c.delta ? 1.0f : 0.0f;
    return g;
}

util::Result<GpuSceneData> packGpuScene(const scene::Scene& scene, const scene::Bvh& bvh,
                                        const RenderOptions& options, bool packEnvTexels) {
    GpuSceneData d;
    auto tables = packGpuBrdfTables(scene);
    if (!tables)
        return tables.error();
    for (size_t i = 0; i <= scene.materials.size(); ++i) {
        auto m = packMaterial(i < scene.materials.size() ? scene.materials[i] : scene::Material{}, i,
                              *tables);
        if (!m)
            return m.error();
        d.materials.push_back(*m);
        const uint32_t plugin = uint32_t(m->emissionType[3]) % plugins::kBrdfTypeCodePlugins;
        d.brdfPlugins |= plugin < 64 ? BrdfPluginSet(1) << plugin : 0;
    }

    // Camera axes exactly as docs/estimator.md "Camera" (and render/reference/cpu_camera.cpp).
    const scene::Camera& cam = scene.camera;
    glm::vec3 forward = glm::normalize(cam.target - cam.position);
    glm::vec3 right = glm::normalize(glm::cross(forward, cam.up));
    glm::vec3 up = glm::cross(right, forward);
    float tanHalf = std::tan(0.5f * cam.verticalFovDeg * kPi / 180.0f);
    float aspect = float(options.width) / float(options.height);
    GpuParams& p = d.params;
    set4(p.camPosition, cam.position, 0.0f);
    set4(p.camForward, forward, tanHalf);
    set4(p.camRight, right, aspect);
    set4(p.camUp, up, 0.0f);

    const scene::Environment& env = scene.lighting.environment;
    float yaw = env.rotationDeg * (kPi / 180.0f);
    set4(p.envScale, env.intensity * env.tint, 0.0f);
    p.envRotation[0] = std::cos(yaw);
    p.envRotation[1] = std::sin(yaw);
    p.size[0] = uint32_t(options.width);
    p.size[1] = uint32_t(options.height);
    p.size[2] = uint32_t(std::max(options.bounces, 0));
    p.size[3] = uint32_t(bvh.triangles.size());
    if (env.image && !env.image->empty()) {
        p.envSize[0] = uint32_t(env.image->width);
        p.envSize[1] = uint32_t(env.image->height);
        if (packEnvTexels) {
            d.envTexels.reserve(env.image->pixels.size() * 3);
            for (const glm::vec3& t : env.image->pixels) {
                d.envTexels.push_back(t.r);
                d.envTexels.push_back(t.g);
                d.envTexels.push_back(t.b);
            }
        }
    }
    p.envSize[2] = uint32_t(d.materials.size());
    for (const scene::Light& l : scene.lighting.lights)
        d.lights.push_back(packGpuLight(l));
    p.envSize[3] = uint32_t(d.lights.size());
    // As LightSet: 1.0f / float(n), computed here so the shader needs no division.
    p.lightInfo[0] = d.lights.empty() ? 0.0f : 1.0f / float(d.lights.size());
    for (const auto& [table, offset] : tables->offsetOf)
        d.usesBrdfTables = d.usesBrdfTables || table != nullptr;
    d.brdfTables = std::move(tables->floats);
    return d;
}

} // namespace wavelit::render
