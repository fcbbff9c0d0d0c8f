// Bounding-volume hierarchy over all triangles of a scene in world space, built on the CPU
// (binned SAH) and flattened in a layout the GPU path tracer reads directly (std430, 32 bytes a
// node: two vec4s). The CPU reference tracer traverses the same arrays, so both tracers see the
// same geometry bit for bit.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace wavelit::scene {

// Interior: count == 0, children at leftFirst and leftFirst + 1.
// Leaf: count > 0 triangles starting at leftFirst in Bvh::triangles.
struct alignas(16) BvhNode {
    float boundsMin[3];
    uint32_t leftFirst;
    float boundsMax[3];
    uint32_t count;
};
static_assert(sizeof(BvhNode) == 32);

// World-space triangle, std430 layout (three vec4s + per-vertex normals as three vec4s).
// w of v0 carries the material index (into Scene::materials; materials.size() when the object's
// material id is unknown: use a default Material{}), w of v1 the object index (into Scene::objects).
// Normals are world space and unit; a mesh without normals gets the geometric normal.
struct alignas(16) BvhTriangle {
    float v0[4];
    float v1[4];
    float v2[4];
    float n0[4];
    float n1[4];
    float n2[4];
};
static_assert(sizeof(BvhTriangle) == 96);

struct Bvh {
    std::vector<BvhNode> nodes; // nodes[0] is the root
    std::vector<BvhTriangle> triangles;
    // Per triangle: its index in its object's mesh (CPU only, not uploaded), so refitObjects can
    // recompute an object's world-space triangles in place after a move.
    std::vector<uint32_t> meshTriangles;
    double buildSeconds = 0.0;
    // bvhSahCost right after buildBvh: a refit that has made the tree much costlier than this
    // is replaced by a fresh build (render/session/bvh_update.cpp).
    float builtSahCost = 0.0f;
};

// One object's non-degenerate world-space triangles in mesh order, as buildBvh makes them
// (material index in v0.w, object index in v1.w), each with its index in the mesh.
struct ObjectTriangle {
    uint32_t meshTriangle;
    BvhTriangle triangle;
};
std::vector<ObjectTriangle> objectTriangles(const Scene& scene, size_t objectIndex);

struct BvhHit {
    float t = 0.0f;
    uint32_t triangle = 0;
    float b1 = 0.0f, b2 = 0.0f; // barycentrics of v1, v2
};

// Builds over every object's mesh transformed to world space. Degenerate (zero-area) triangles
// are skipped. An empty scene gives a single node and no triangles (traversal checks for that).
Bvh buildBvh(const Scene& scene);

// Expected cost of a ray through the tree relative to the root box (surface-area heuristic: sum
// over nodes of area / root area, times the triangle count at leaves, 1 per interior node).
float bvhSahCost(const Bvh& bvh);

// Closest hit along origin + t * dir for t in (tMin, tMax); false if none.
bool intersect(const Bvh& bvh, const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax,
               BvhHit& hit);
// Any hit (shadow rays).
bool occluded(const Bvh& bvh, const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax);

} // namespace wavelit::scene
