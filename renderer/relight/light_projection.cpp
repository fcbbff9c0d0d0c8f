#include "relight/light_projection.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace wavelit::relight {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kMaxSide = 6;
// A rect's samples per texel it covers. Its per-point cost (the projection, then f and the
// visibility per texel entry) scales with the samples; measured on ring_on_ground and the Cornell
// box at 128^2 against the 512-spp reference, relRMSE 0.1300 / 0.0867 at 1 per texel, 0.1297 /
// 0.0869 at 1/2 and 0.1336 / 0.0930 at 1/4, at 131 / 81 / 54 CPU ms per softbox drag (256^2
// points; docs/relighting.md §7.0a). A lambert or broad glossy f varies little
// across neighbouring texels, so where the light's total lands between them barely matters.
constexpr double kRectSamplesPerTexel = 0.5;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Basis {
    glm::vec3 t, b;
};
Basis basisAround(const glm::vec3& n) {
    const glm::vec3 ref = std::abs(n.y) > 0.999f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const glm::vec3 t = glm::normalize(glm::cross(ref, n));
    return {t, glm::cross(n, t)};
}

// Samples per side for a source of solid angle omega: about samplesPerTexel per texel it covers (the
// weights only decide how the light's total splits between neighbouring texels; mapping the
// samples to texels is most of a light edit's time).
int sidesFor(double omega, const TexelDirections& dirs, double samplesPerTexel = 1.0) {
    const double texels = omega / dirs.texelSolidAngle() * samplesPerTexel;
    return std::clamp(int(std::ceil(std::sqrt(texels))), 1, kMaxSide);
}

// Collects the samples' (texel, weight, distance) into `out`, merged per texel: at most
// kMaxSide^2 samples, so a sorted insertion into the caller's buffer beats a sort and keeps a
// light edit free of allocations (it runs once per point per edit).
class Accumulator {
public:
    Accumulator(const TexelDirections& dirs, std::vector<TexelWeight>& out) : m_dirs(dirs), m_out(out) {
        m_out.clear();
        m_out.reserve(kMaxSide * kMaxSide);
    }
    void add(const glm::vec3& dir, const glm::vec3& weight, float distance) {
        const glm::vec3 unit = glm::normalize(dir);
        const uint32_t texel = m_dirs.texelOfUnit(unit);
        size_t i = m_out.size();
        while (i > 0 && m_out[i - 1].texel > texel) --i;
        const float w = weight.x + weight.y + weight.z;
        // The sample's point on the light relative to p (its direction alone for the sun): the
        // entry's shadow ray aims at their weighted mean, which for a rect lies on the light.
        // (A ray along the texel's centre up to the samples' mean distance overshoots the light
        // where the texel's centre misses it: under the Cornell box's ceiling, 2 cm above its
        // light, that put the ceiling in the way of about half the light's texels.)
        const glm::vec3 point = std::isfinite(distance) ? unit * distance : unit;
        if (i > 0 && m_out[i - 1].texel == texel) {
            m_out[i - 1].weight += weight;
            m_out[i - 1].direction += point * w;
            return;
        }
        m_out.insert(m_out.begin() + std::ptrdiff_t(i), TexelWeight{texel, weight, distance, point * w});
    }
    // The light is smaller than a quarter texel: one sample carries it all.
    void markCompact() { m_compact = true; }
    void finish() {
        for (TexelWeight& e : m_out) {
            // direction holds sum of w x point: the mean point's distance (finite lights) and
            // its direction.
            const float w = e.weight.x + e.weight.y + e.weight.z;
            const float len = glm::length(e.direction);
            if (std::isfinite(e.distance) && w > 0.0f) e.distance = len / w;
            e.direction = len > 0.0f ? e.direction / len : m_dirs.direction(e.texel);
        }
        std::erase_if(m_out, [](const TexelWeight& e) { return e.weight == glm::vec3(0.0f); });
        for (TexelWeight& e : m_out) e.compact = m_compact;
    }

private:
    const TexelDirections& m_dirs;
    std::vector<TexelWeight>& m_out;
    bool m_compact = false;
};

// Uniform radiance `radiance` over the cone of half angle with 1 - cos = oneMinusCos about axis.
void addCone(Accumulator& acc, const TexelDirections& dirs, const glm::vec3& axis,
             double oneMinusCos, const glm::vec3& radiance, float distance) {
    const double omega = 2.0 * kPi * oneMinusCos;
    const glm::vec3 total = radiance * float(omega);
    if (omega < 0.25 * dirs.texelSolidAngle()) {
        acc.markCompact();
        return acc.add(axis, total, distance);
    }
    const int s = sidesFor(omega, dirs);
    const Basis basis = basisAround(axis);
    const glm::vec3 each = total / float(s * s);
    for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
            // Uniform in the cone: cos theta uniform in [1 - oneMinusCos, 1].
            const double u1 = (i + 0.5) / s, u2 = (j + 0.5) / s;
            const double cosT = 1.0 - u1 * oneMinusCos;
            const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
            const double phi = 2.0 * kPi * u2;
            const glm::vec3 d = float(cosT) * axis + float(sinT * std::cos(phi)) * basis.t +
                                float(sinT * std::sin(phi)) * basis.b;
            acc.add(d, each, distance);
        }
}

// A rect's s x s samples straight into `out`: per sample one direction, one texel lookup and a
// scalar weight (cos at the light / distance^2; the light's radiance is uniform, so the entry's
// RGB weight is radiance x sample area x the sum), merged per texel in a small local table.
// The projection was 60% of a rect drag's per-point cost (docs/relighting.md §7.0a). Here: no
// Accumulator, no second normalisation, no sorted insertion of 48-byte entries per sample.
void projectRect(const TexelDirections& dirs, const scene::Light& light, const glm::vec3& power,
                 const glm::vec3& p, std::vector<TexelWeight>& out) {
    out.clear();
    const float area = light.size.x * light.size.y;
    const float len = glm::length(light.direction);
    if (!(area > 0.0f) || !(len > 0.0f)) return;
    const glm::vec3 n = light.direction / len;
    const Basis basis = basisAround(n); // U = normalize(cross(ref, n)), V = cross(n, U)
    const glm::vec3 radiance = power * float(1.0 / (kPi * double(area)));
    const glm::vec3 toP = p - light.position;
    const float d2 = glm::dot(toP, toP);
    if (!(glm::dot(toP, n) > 0.0f) || !(d2 > 0.0f)) return; // behind the emitting face
    const double omega = double(area) * glm::dot(toP, n) / std::sqrt(d2) / d2;
    const bool compact = omega < 0.25 * dirs.texelSolidAngle();
    const int s = compact ? 1 : sidesFor(omega, dirs, kRectSamplesPerTexel);
    struct Bin {
        uint32_t texel;
        float weight;   // sum of cos / distance^2 over the samples in the texel
        glm::vec3 sum;  // sum of weight x (sample point - p)
    };
    Bin bins[kMaxSide * kMaxSide];
    int count = 0;
    constexpr uint32_t kSlots = 128; // > 3 x the most bins: short probe runs
    uint8_t slot[kSlots] = {};       // bin index + 1, 0: empty
    const glm::vec3 du = basis.t * (light.size.x / float(s)), dv = basis.b * (light.size.y / float(s));
    const glm::vec3 first = toP * -1.0f + basis.t * (-0.5f * light.size.x) + basis.b * (-0.5f * light.size.y) +
                            0.5f * (du + dv);
    // Two passes: the samples' texels first (independent work the CPU overlaps; the texel map
    // is a chain of dependent multiplies), then their merge per texel, whose probe branches
    // would stall the first pass if interleaved with it.
    glm::vec3 offsets[kMaxSide * kMaxSide];
    float weights[kMaxSide * kMaxSide];
    uint32_t texels[kMaxSide * kMaxSide];
    int samples = 0;
    for (int j = 0; j < s; ++j) {
        const glm::vec3 row = first + float(j) * dv;
        for (int i = 0; i < s; ++i) {
            const glm::vec3 d = row + float(i) * du; // sample point - p
            const float dist2 = glm::dot(d, d);
            const float inv = 1.0f / std::sqrt(dist2);
            const glm::vec3 unit = d * inv;
            const float cosLight = -glm::dot(unit, n);
            if (!(cosLight > 0.0f)) continue;
            offsets[samples] = d;
            weights[samples] = cosLight * inv * inv;
            texels[samples] = dirs.texelOfUnit(unit);
            ++samples;
        }
    }
    for (int k = 0; k < samples; ++k) {
        const uint32_t texel = texels[k];
        // Open addressing on the texel's low bits: a linear search over the bins was O(n^2).
        uint32_t h = texel & (kSlots - 1);
        while (slot[h] != 0 && bins[slot[h] - 1].texel != texel) h = (h + 1) & (kSlots - 1);
        if (slot[h] == 0) {
            bins[count] = Bin{texel, 0.0f, glm::vec3(0.0f)};
            slot[h] = uint8_t(++count);
        }
        Bin& bin = bins[slot[h] - 1];
        bin.weight += weights[k];
        bin.sum += offsets[k] * weights[k];
    }
    // Ascending texel order: sort 32-bit keys (texel, bin), not the bins (a sorted insertion of
    // the bins was half the projection's time: the samples run across texels in any order).
    uint32_t keys[kMaxSide * kMaxSide];
    for (int k = 0; k < count; ++k) keys[k] = (bins[k].texel << 6) | uint32_t(k);
    std::sort(keys, keys + count);
    const glm::vec3 each = radiance * (area / float(s * s));
    out.resize(size_t(count));
    size_t used = 0;
    for (int k = 0; k < count; ++k) {
        const Bin& bin = bins[keys[k] & 63u];
        const glm::vec3 weight = each * bin.weight;
        if (weight == glm::vec3(0.0f)) continue;
        // The shadow ray aims at the weighted mean of the samples' points, which lies on the light.
        const float l = glm::length(bin.sum);
        TexelWeight& e = out[used++];
        e.texel = bin.texel;
        e.weight = weight;
        e.distance = bin.weight > 0.0f ? l / bin.weight : 0.0f;
        e.direction = l > 0.0f ? bin.sum * (1.0f / l) : dirs.direction(bin.texel);
        e.compact = compact;
    }
    out.resize(used);
}

float spotFalloff(const scene::Light& light, const glm::vec3& fromLight) {
    const glm::vec3 axis = glm::normalize(light.direction);
    const float cosAlpha = glm::dot(fromLight, axis);
    const float cosInner = float(std::cos(double(light.coneInnerDeg) * kPi / 180.0));
    const float cosOuter = float(std::cos(double(light.coneOuterDeg) * kPi / 180.0));
    if (!(cosInner > cosOuter)) return cosAlpha >= cosOuter ? 1.0f : 0.0f;
    const float t = std::clamp((cosAlpha - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

} // namespace

scene::Light unitPowerLight(const scene::Light& light) {
    scene::Light unit = light;
    unit.color = glm::vec3(1.0f);
    unit.intensity = 1.0f;
    return unit;
}

glm::vec3 lightPower(const scene::Light& light) { return light.color * light.intensity; }

std::vector<TexelWeight> projectLight(const scene::Light& light, const glm::vec3& p,
                                      const TexelDirections& dirs) {
    std::vector<TexelWeight> out;
    projectLight(light, p, dirs, out);
    return out;
}

void projectLight(const scene::Light& light, const glm::vec3& p, const TexelDirections& dirs,
                  std::vector<TexelWeight>& out) {
    projectLightWithPower(light, light.color * light.intensity, p, dirs, out);
}

void projectUnitLight(const scene::Light& light, const glm::vec3& p, const TexelDirections& dirs,
                      std::vector<TexelWeight>& out) {
    projectLightWithPower(light, glm::vec3(1.0f), p, dirs, out);
}

void projectLightWithPower(const scene::Light& light, const glm::vec3& power, const glm::vec3& p,
                           const TexelDirections& dirs, std::vector<TexelWeight>& out) {
    if (light.type == scene::LightType::Rect) return projectRect(dirs, light, power, p, out);
    Accumulator acc(dirs, out);
    const glm::vec3 toLight = light.position - p;
    const float d2 = glm::dot(toLight, toLight);
    switch (light.type) {
    case scene::LightType::Sphere:
        if (light.radius > 0.0f) {
            const float r2 = light.radius * light.radius;
            if (!(d2 > r2)) break; // inside: the surface emits outward only
            const double sin2 = double(r2) / double(d2);
            const double oneMinusCos = sin2 / (1.0 + std::sqrt(1.0 - sin2));
            // Shadow rays stop at the sphere's near side along its centre direction.
            addCone(acc, dirs, toLight / std::sqrt(d2), oneMinusCos,
                    power * float(1.0 / (4.0 * kPi * kPi * double(r2))), std::sqrt(d2) - light.radius);
            break;
        }
        [[fallthrough]];
    case scene::LightType::Point:
    case scene::LightType::Spot: {
        if (!(d2 > 0.0f)) break;
        const glm::vec3 dir = toLight / std::sqrt(d2);
        const float falloff = light.type == scene::LightType::Spot ? spotFalloff(light, -dir) : 1.0f;
        acc.markCompact();
        acc.add(dir, power * float(1.0 / (4.0 * kPi)) * falloff / d2, std::sqrt(d2));
        break;
    }
    case scene::LightType::Rect: break; // projectRect above
    case scene::LightType::Sun: {
        const float len = glm::length(light.direction);
        if (!(len > 0.0f)) break;
        const glm::vec3 axis = -light.direction / len;
        const double half = 0.5 * double(light.angularDiameterDeg) * kPi / 180.0;
        if (half <= 0.0) {
            acc.markCompact();
            acc.add(axis, power, kInfinity);
            break;
        }
        const double s = std::sin(half), sHalf = std::sin(0.5 * half);
        addCone(acc, dirs, axis, 2.0 * sHalf * sHalf, power * float(1.0 / (kPi * s * s)), kInfinity);
        break;
    }
    }
    acc.finish();
}

} // namespace wavelit::relight
