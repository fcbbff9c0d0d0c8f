#include "relight/object_occluder.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace wavelit::relight {

ObjectOccluder buildObjectOccluder(const scene::Scene& scene, size_t objectIndex) {
    scene::Scene single;
    single.objects = {scene.objects[objectIndex]};
    ObjectOccluder o;
    o.bvh = scene::buildBvh(single);
    if (o.bvh.triangles.empty()) return o;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const scene::BvhTriangle& t : o.bvh.triangles)
        for (const float* v : {t.v0, t.v1, t.v2}) {
            lo = glm::min(lo, glm::vec3(v[0], v[1], v[2]));
            hi = glm::max(hi, glm::vec3(v[0], v[1], v[2]));
        }
    o.bounds.centre = 0.5f * (lo + hi);
    float r2 = 0.0f;
    for (const scene::BvhTriangle& t : o.bvh.triangles)
        for (const float* v : {t.v0, t.v1, t.v2}) {
            const glm::vec3 d = glm::vec3(v[0], v[1], v[2]) - o.bounds.centre;
            r2 = std::max(r2, glm::dot(d, d));
        }
    // Padded so float rounding of the vertices never puts a surface outside the sphere.
    o.bounds.radius = std::sqrt(r2) * 1.0001f + 1e-5f;
    return o;
}

TexelBits coneTexels(const BoundingSphere& sphere, const glm::vec3& p, const TexelDirections& dirs,
                     const TexelBits& candidates) {
    TexelBits out = makeBits(dirs.count());
    if (sphere.radius < 0.0f) return out;
    const glm::vec3 toCentre = sphere.centre - p;
    const float distance = glm::length(toCentre);
    if (distance <= sphere.radius) return candidates; // inside: every direction may hit
    const glm::vec3 axis = toCentre / distance;
    const double half = std::asin(double(sphere.radius) / double(distance)) + dirs.texelRadius();
    const float cosHalf = half >= 3.14159265358979 ? -2.0f : float(std::cos(half));
    for (size_t w = 0; w < candidates.size(); ++w)
        for (uint64_t bits = candidates[w]; bits; bits &= bits - 1) {
            const size_t t = w * 64 + size_t(__builtin_ctzll(bits));
            if (glm::dot(dirs.direction(t), axis) >= cosHalf) setBit(out, t);
        }
    return out;
}

TexelBits castOcclusion(const ObjectOccluder& occluder, const glm::vec3& origin,
                        const TexelDirections& dirs, const TexelBits& candidates) {
    TexelBits out = makeBits(dirs.count());
    for (size_t w = 0; w < candidates.size(); ++w)
        for (uint64_t bits = candidates[w]; bits; bits &= bits - 1) {
            const size_t t = w * 64 + size_t(__builtin_ctzll(bits));
            if (scene::occluded(occluder.bvh, origin, dirs.direction(t), 0.0f,
                                std::numeric_limits<float>::max()))
                setBit(out, t);
        }
    return out;
}

} // namespace wavelit::relight
