#include "relight/shadow_field.h"

#include "util/parallel_for.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

namespace wavelit::relight {

ShadowField ShadowField::build(const ObjectOccluder& occluder, const TexelDirections& maskDirs,
                               const ShadowFieldSettings& settings, int threads, const std::atomic<bool>* cancel) {
    ShadowField f;
    f.m_settings = settings;
    f.m_dirs = std::make_shared<const TexelDirections>(settings.directionLevel);
    f.m_words = makeBits(maskDirs.count()).size();
    f.m_maskTexels = maskDirs.count();
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
    f.m_inside.assign(shells * dirCount, 0);
    TexelBits all = makeBits(maskDirs.count());
    for (size_t t = 0; t < maskDirs.count(); ++t) setBit(all, t);
    util::parallelFor(shells * dirCount, threads, [&](size_t n) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return;
        const glm::vec3 origin = occluder.bounds.centre + f.sampleOffset(n / dirCount, n % dirCount);
        const TexelBits cone = coneTexels(occluder.bounds, origin, maskDirs, all);
        if (!anyBit(cone)) return;
        const TexelBits blocked = castOcclusion(occluder, origin, maskDirs, cone);
        std::copy(blocked.begin(), blocked.end(), f.m_masks.begin() + std::ptrdiff_t(n * f.m_words));
        size_t count = 0;
        for (uint64_t w : blocked) count += size_t(__builtin_popcountll(w));
        f.m_inside[n] = double(count) >= 0.98 * double(maskDirs.count()) ? 1 : 0; // reported only
    });
    return f;
}

glm::vec3 ShadowField::sampleOffset(size_t shell, size_t direction) const {
    return m_dirs->direction(direction) * m_radii[shell];
}

const uint64_t* ShadowField::sampleMask(size_t shell, size_t direction) const {
    return &m_masks[(shell * m_dirs->count() + direction) * m_words];
}

size_t ShadowField::insideSamples() const {
    return size_t(std::count(m_inside.begin(), m_inside.end(), uint8_t(1)));
}

const uint64_t* ShadowField::lookup(const glm::vec3& offset) const {
    const float d = glm::length(offset);
    if (!(d < m_reach)) return nullptr;
    const float x = d > 0.0f ? (std::log(d) - m_logInner) / m_logStep : 0.0f;
    const size_t shell = size_t(std::clamp(std::lround(x), 0l, long(m_radii.size()) - 1));
    const size_t direction = d > 0.0f ? m_dirs->texelOfUnit(offset / d) : 0;
    return sampleMask(shell, direction);
}

bool ShadowField::blend(const glm::vec3& offset, Blend& out) const {
    out.count = 0;
    const float d = glm::length(offset);
    if (!(d < m_reach)) return false;
    const float x = d > 0.0f ? std::clamp((std::log(d) - m_logInner) / m_logStep, 0.0f, float(m_radii.size() - 1)) : 0.0f;
    // Within 1e-3 of a sample's coordinate, that sample's alone (float rounding of the map).
    auto snap = [](float& c) { c = std::abs(c - std::round(c)) < 1e-3f ? std::round(c) : c; };
    float xr = x;
    snap(xr);
    const size_t s0 = size_t(xr), s1 = std::min(s0 + 1, m_radii.size() - 1);
    const float fs = xr - float(s0);
    // The offset's continuous position on the octahedral square (texelOfUnit's map), in texel
    // units with texel centres at integers.
    const glm::vec3 u3 = d > 0.0f ? offset / d : glm::vec3(0.0f, 1.0f, 0.0f);
    const float dx = u3.x, dy = u3.z, dz = u3.y;
    const float ax = std::abs(dx), ay = std::abs(dy), az = std::abs(dz);
    const float r = std::sqrt(std::max(0.0f, 1.0f - az));
    const float a = std::max(ax, ay);
    const float b = a == 0.0f ? 0.0f : std::min(ax, ay) / a;
    float phi = std::atan(b) * float(2.0 / 3.14159265358979);
    phi = ax < ay ? 1.0f - phi : phi;
    const float v0 = phi * r, u0 = r - v0;
    const bool lower = dz < 0.0f;
    const float u = lower ? 1.0f - v0 : u0, v = lower ? 1.0f - u0 : v0;
    const int n = m_dirs->side();
    float px = std::clamp(0.5f * (std::copysign(u, dx) + 1.0f) * float(n) - 0.5f, 0.0f, float(n - 1));
    float py = std::clamp(0.5f * (std::copysign(v, dy) + 1.0f) * float(n) - 0.5f, 0.0f, float(n - 1));
    snap(px);
    snap(py);
    const int x0 = int(px), y0 = int(py);
    const int x1 = std::min(x0 + 1, n - 1), y1 = std::min(y0 + 1, n - 1);
    const float fx = px - float(x0), fy = py - float(y0);
    const int xs[2] = {x0, x1}, ys[2] = {y0, y1};
    const float wx[2] = {1.0f - fx, fx}, wy[2] = {1.0f - fy, fy};
    const size_t shellsOf[2] = {s0, s1};
    const float wsh[2] = {1.0f - fs, fs};
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                const float w = wsh[k] * wy[j] * wx[i];
                const size_t sample = shellsOf[k] * m_dirs->count() + size_t(ys[j] * n + xs[i]);
                if (!(w > 0.0f)) continue;
                out.masks[out.count] = &m_masks[sample * m_words];
                out.weights[out.count] = w;
                ++out.count;
            }
    float total = 0.0f;
    for (int k = 0; k < out.count; ++k) total += out.weights[k];
    if (!(total > 0.0f)) {
        out.count = 0;
        return false;
    }
    for (int k = 0; k < out.count; ++k) out.weights[k] /= total;
    return true;
}

} // namespace wavelit::relight
