#include "relight/object_occluder.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <vector>
#include <limits>

namespace wavelit::relight {

namespace {

// Every vertex on or below every triangle's plane (sign -1: above), within a tolerance far below
// the rays' surface offset (1e-4 x max(1, |p|)).
bool allBelowEveryPlane(const std::vector<glm::vec3>& vertices, const scene::TriangleMesh& mesh, float sign) {
    float extent = 0.0f;
    for (const glm::vec3& v : vertices) extent = std::max(extent, glm::length(v));
    const float tolerance = 1e-6f * std::max(1.0f, extent);
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3& a = mesh.positions[mesh.indices[t]];
        const glm::vec3 n = sign * glm::cross(mesh.positions[mesh.indices[t + 1]] - a,
                                              mesh.positions[mesh.indices[t + 2]] - a);
        const float len = glm::length(n);
        if (!(len > 0.0f)) continue;
        for (const glm::vec3& v : vertices)
            if (glm::dot(n, v - a) > tolerance * len) return false;
    }
    return true;
}

} // namespace

MeshConvexity meshConvexity(const scene::TriangleMesh& mesh) {
    MeshConvexity c;
    // Quadratic: a mesh too large for it is simply treated as not convex (rays as before).
    if (mesh.indices.empty() || double(mesh.triangleCount()) * double(mesh.positions.size()) > 2e8) return c;
    std::vector<glm::vec3> vertices;
    for (uint32_t i : mesh.indices) vertices.push_back(mesh.positions[i]);
    std::sort(vertices.begin(), vertices.end(), [](const glm::vec3& a, const glm::vec3& b) {
        return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    });
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    c.front = allBelowEveryPlane(vertices, mesh, 1.0f);
    c.back = allBelowEveryPlane(vertices, mesh, -1.0f);
    return c;
}

ObjectOccluder buildObjectOccluder(const scene::Scene& scene, size_t objectIndex, ConvexityCache& cache) {
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
    const scene::Object& object = scene.objects[objectIndex];
    if (object.mesh) {
        auto it = cache.find(object.mesh);
        if (it == cache.end()) it = cache.emplace(object.mesh, meshConvexity(*object.mesh)).first;
        const float det = glm::determinant(glm::mat3(object.transform.matrix()));
        if (det > 0.0f) {
            o.convexFront = it->second.front;
            o.convexBack = it->second.back;
        } else if (det < 0.0f) { // a mirror turns the triangles' winding
            o.convexFront = it->second.back;
            o.convexBack = it->second.front;
        }
    }
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
