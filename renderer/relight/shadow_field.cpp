#include "relight/shadow_field.h"

#include "relight/parallel_for.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

namespace wavelit::relight {

ShadowField ShadowField::build(const ObjectOccluder& occluder, const TexelDirections& maskDirs,
                               const ShadowFieldSettings& settings, int threads) {
    ShadowField f;
    f.m_settings = settings;
    f.m_dirs = std::make_shared<const TexelDirections>(settings.directionLevel);
    f.m_words = makeBits(maskDirs.count()).size();
    const size_t shells = size_t(std::max(1, settings.shells));
    const float radius = std::max(occluder.bounds.radius, 1e-6f);
    const float inner = settings.innerRatio * radius, outer = std::max(settings.outerRatio, settings.innerRatio) * radius;
    f.m_logInner = std::log(inner);
    f.m_logStep = shells > 1 ? (std::log(outer) - f.m_logInner) / float(shells - 1) : 1.0f;
    for (size_t i = 0; i < shells; ++i) f.m_radii.push_back(std::exp(f.m_logInner + f.m_logStep * float(i)));
    // Nearest-shell lookups reach half a step (in log radius) past the outer shell.
    f.m_reach = std::exp(f.m_logInner + f.m_logStep * (float(shells) - 0.5f));
    const size_t dirCount = f.m_dirs->count();
    f.m_masks.assign(shells * dirCount * f.m_words, 0);
    TexelBits all = makeBits(maskDirs.count());
    for (size_t t = 0; t < maskDirs.count(); ++t) setBit(all, t);
    parallelFor(shells * dirCount, threads, [&](size_t n) {
        const glm::vec3 origin = occluder.bounds.centre + f.sampleOffset(n / dirCount, n % dirCount);
        const TexelBits cone = coneTexels(occluder.bounds, origin, maskDirs, all);
        if (!anyBit(cone)) return;
        const TexelBits blocked = castOcclusion(occluder, origin, maskDirs, cone);
        std::copy(blocked.begin(), blocked.end(), f.m_masks.begin() + std::ptrdiff_t(n * f.m_words));
    });
    return f;
}

glm::vec3 ShadowField::sampleOffset(size_t shell, size_t direction) const {
    return m_dirs->direction(direction) * m_radii[shell];
}

const uint64_t* ShadowField::sampleMask(size_t shell, size_t direction) const {
    return &m_masks[(shell * m_dirs->count() + direction) * m_words];
}

const uint64_t* ShadowField::lookup(const glm::vec3& offset) const {
    const float d = glm::length(offset);
    if (!(d < m_reach)) return nullptr;
    const float x = d > 0.0f ? (std::log(d) - m_logInner) / m_logStep : 0.0f;
    const size_t shell = size_t(std::clamp(std::lround(x), 0l, long(m_radii.size()) - 1));
    const size_t direction = d > 0.0f ? m_dirs->texelOfUnit(offset / d) : 0;
    return sampleMask(shell, direction);
}

} // namespace wavelit::relight
