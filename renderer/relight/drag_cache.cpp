#include "relight/drag_cache.h"

#include "relight/texel_values.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace wavelit::relight {
namespace {

// The set bits of x, inline: the baseline x86-64 target has no popcnt instruction, and the
// library call __builtin_popcountll makes there was ~3% of a drag step (one per blocked texel).
inline unsigned bitCount(uint64_t x) {
    x -= (x >> 1) & 0x5555555555555555u;
    x = (x & 0x3333333333333333u) + ((x >> 2) & 0x3333333333333333u);
    x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fu;
    return unsigned((x * 0x0101010101010101u) >> 56);
}

bool allGrey(const std::vector<glm::vec3>& v) {
    for (const glm::vec3& x : v)
        if (x.x != x.y || x.x != x.z) return false;
    return true;
}

void append(std::vector<float>& out, const std::vector<glm::vec3>& v, int channels) {
    for (const glm::vec3& x : v)
        for (int c = 0; c < channels; ++c) out.push_back(x[c]);
}

// Whether j, blocking the texel of `e` at infinity, lies between the point and the light: always
// for the sun; for a local light when j's bounding sphere starts before the light along e's
// direction (a ray that misses the sphere cannot hit j).
bool blocksEntry(const LightContribution& e, const BoundingSphere& sphere, const glm::vec3& origin,
                 const scene::Bvh* objectBvh) {
    if (!std::isfinite(e.distance)) return true;
    if (objectBvh) return scene::occluded(*objectBvh, origin, e.direction, 0.0f, e.distance * (1.0f - 1e-3f));
    const glm::vec3 oc = sphere.centre - origin;
    const float c = glm::dot(oc, oc) - sphere.radius * sphere.radius;
    if (c <= 0.0f) return true; // inside the sphere
    const float b = glm::dot(oc, e.direction);
    const float disc = b * b - c;
    if (b <= 0.0f || disc < 0.0f) return false;
    return b - std::sqrt(disc) < e.distance;
}

} // namespace

size_t PointDragCache::bytes() const {
    size_t b = sizeof(PointDragCache) + visible.capacity() * sizeof(uint64_t) + rank.capacity() * sizeof(uint16_t) +
               values.capacity() * sizeof(float) + lights.capacity() * sizeof(lights[0]);
    for (const auto& l : lights) b += l.capacity() * sizeof(LightContribution);
    b += lightTexels.capacity() * sizeof(lightTexels[0]) + (lightSum.capacity() + lightSum0.capacity()) * sizeof(glm::vec3);
    for (const TexelBits& t : lightTexels) b += t.capacity() * sizeof(uint64_t);
    return b;
}

PointDragCache buildDragCache(const TransferContext& ctxWithout, const PreviewPoint& p, const PointState& without,
                              const std::vector<glm::vec3>* envTexels) {
    PointDragCache c;
    c.valid = true;
    c.visible = without.lit;
    for (const Occlusion& o : without.occlusions)
        for (size_t w = 0; w < c.visible.size(); ++w) c.visible[w] &= ~o.blocked[w];
    c.rank.resize(c.visible.size());
    uint32_t count = 0;
    for (size_t w = 0; w < c.visible.size(); ++w) {
        c.rank[w] = uint16_t(count);
        count += uint32_t(__builtin_popcountll(c.visible[w]));
    }
    // T' at the visible texels (rebuildTransfer's values: a grey-affine BRDF's are grey already).
    thread_local TexelValues values;
    visibleTexelValues(ctxWithout, p, without, materialOf(ctxWithout, p).colourUse == ColourUse::Affine, values);
    c.affine = envTexels ? !values.black.empty() : !without.transfer0.index.empty();
    c.channels = allGrey(values.white) && allGrey(values.black) ? 1 : 3;
    append(c.values, values.white, c.channels);
    if (c.affine) append(c.values, values.black, c.channels);
    c.envBase = without.envTerm;
    c.envBase0 = without.envTerm0;
    if (envTexels) { // untruncated, as untruncatedTerms sums them
        glm::dvec3 env, env0;
        environmentSums(values, *envTexels, env, env0);
        c.envBase = glm::vec3(env);
        c.envBase0 = glm::vec3(env0);
    }
    const auto& lights = ctxWithout.scene->lighting.lights;
    c.lights.resize(lights.size());
    c.lightTexels.assign(lights.size(), makeBits(ctxWithout.dirs->count()));
    c.lightSum.assign(lights.size(), glm::vec3(0.0f));
    c.lightSum0.assign(lights.size(), glm::vec3(0.0f));
    for (size_t k = 0; k < lights.size(); ++k) {
        seenLightContributions(ctxWithout, p, without, lights[k], c.lights[k]);
        for (const LightContribution& e : c.lights[k]) { // applyDragMask's sums with nothing blocked
            setBit(c.lightTexels[k], e.texel);
            c.lightSum[k] += e.white;
            c.lightSum0[k] += e.black;
        }
    }
    return c;
}

void applyDragMask(const PointDragCache& cache, const uint64_t* mask, const BoundingSphere& sphere,
                   const glm::vec3& origin, const std::vector<glm::vec3>& envTexels, PointState& s,
                   const scene::Bvh* objectBvh, const float* weight) {
    glm::dvec3 cut(0.0), cut0(0.0);
    const size_t visibleCount = cache.values.size() / (size_t(cache.channels) * (cache.affine ? 2 : 1));
    const size_t blackAt = visibleCount * cache.channels;
    if (mask)
        for (size_t w = 0; w < cache.visible.size(); ++w)
            for (uint64_t bits = mask[w] & cache.visible[w]; bits; bits &= bits - 1) {
                const unsigned b = unsigned(__builtin_ctzll(bits));
                const size_t t = w * 64 + b;
                const size_t r = cache.rank[w] + size_t(bitCount(cache.visible[w] & ((uint64_t(1) << b) - 1)));
                const glm::dvec3 l = glm::dvec3(envTexels[t]) * (weight ? double(weight[t]) : 1.0);
                const float* v = &cache.values[r * cache.channels];
                cut += cache.channels == 1 ? l * double(v[0]) : l * glm::dvec3(v[0], v[1], v[2]);
                if (cache.affine) {
                    const float* v0 = &cache.values[blackAt + r * cache.channels];
                    cut0 += cache.channels == 1 ? l * double(v0[0]) : l * glm::dvec3(v0[0], v0[1], v0[2]);
                }
            }
    s.envTerm = glm::vec3(glm::dvec3(cache.envBase) - cut);
    s.envTerm0 = cache.affine ? glm::vec3(glm::dvec3(cache.envBase0) - cut0) : glm::vec3(0.0f);
    s.lightTerms.assign(cache.lights.size(), glm::vec3(0.0f));
    if (cache.affine) s.lightTerms0.assign(cache.lights.size(), glm::vec3(0.0f));
    else s.lightTerms0.clear();
    for (size_t k = 0; k < cache.lights.size(); ++k) {
        bool masked = false;
        if (mask)
            for (size_t w = 0; w < cache.lightTexels[k].size() && !masked; ++w) masked = (mask[w] & cache.lightTexels[k][w]) != 0;
        if (!masked) { // the loop below would add every entry in order: its sums, bit for bit
            s.lightTerms[k] = cache.lightSum[k];
            if (cache.affine) s.lightTerms0[k] = cache.lightSum0[k];
            continue;
        }
        glm::vec3 sum(0.0f), sum0(0.0f);
        for (const LightContribution& e : cache.lights[k]) {
            if (mask && ((mask[e.texel >> 6] >> (e.texel & 63)) & 1u) && blocksEntry(e, sphere, origin, objectBvh)) {
                if (!weight || weight[e.texel] >= 1.0f) continue;
                const float open = 1.0f - weight[e.texel];
                sum += e.white * open;
                sum0 += e.black * open;
                continue;
            }
            sum += e.white;
            sum0 += e.black;
        }
        s.lightTerms[k] = sum;
        if (cache.affine) s.lightTerms0[k] = sum0;
    }
}

} // namespace wavelit::relight
