#include "render/lights/light_set.h"

#include <algorithm>

namespace wavelit::render {

float powerHeuristic(float a, float b) {
    if (!(a > 0.0f)) return 0.0f;
    const float r = b / a;
    return 1.0f / (1.0f + r * r);
}

LightSet::LightSet(const std::vector<scene::Light>& lights) {
    m_lights.reserve(lights.size());
    for (const scene::Light& l : lights) m_lights.emplace_back(l);
    if (!m_lights.empty()) m_selection = 1.0f / float(m_lights.size());
}

size_t LightSet::select(float u) const {
    return std::min(size_t(u * float(m_lights.size())), m_lights.size() - 1);
}

float LightSet::lightWeight(const LightSampler& light, float lightPdf, float bsdfPdf,
                            LightStrategy strategy) const {
    if (light.isDelta()) return 1.0f;
    switch (strategy) {
    case LightStrategy::Mis: return powerHeuristic(m_selection * lightPdf, bsdfPdf);
    case LightStrategy::LightOnly: return 1.0f;
    case LightStrategy::BsdfOnly: return 0.0f;
    }
    return 0.0f;
}

glm::vec3 LightSet::emissionAlongRay(const glm::vec3& origin, const glm::vec3& dir, float tMax,
                                     float bsdfPdf, bool cameraRay, LightStrategy strategy,
                                     glm::vec3* perLight) const {
    glm::vec3 sum(0.0f);
    for (size_t k = 0; k < m_lights.size(); ++k) {
        const LightSampler& light = m_lights[k];
        if (perLight) perLight[k] = glm::vec3(0.0f);
        auto hit = light.evalHit(origin, dir, tMax);
        if (!hit) continue;
        float w = 1.0f;
        if (!cameraRay) {
            switch (strategy) {
            case LightStrategy::Mis:
                w = powerHeuristic(bsdfPdf, m_selection * light.pdf(origin, dir));
                break;
            case LightStrategy::LightOnly: w = 0.0f; break;
            case LightStrategy::BsdfOnly: w = 1.0f; break;
            }
        }
        sum += w * hit->radiance;
        if (perLight) perLight[k] = w * hit->radiance;
    }
    return sum;
}

} // namespace wavelit::render
