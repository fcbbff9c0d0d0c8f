// One object as an occluder of the preview points: its own CPU BVH (so its occlusion factor O_j
// is ray-cast against it alone, paper eq 21) and a bounding sphere of its world-space triangles.
// The sphere bounds the region the object can shadow: from a point p outside it, the object lies
// inside the cone of half angle asin(r / |c - p|) about c - p, so O_j = 1 outside that cone and
// only the texels the cone touches are ray-cast (architecture.md §7: factors of objects that
// cannot shadow a point are not built).
#pragma once

#include "relight/texel_directions.h"
#include "scene/bvh.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <map>
#include <memory>

namespace wavelit::relight {

struct BoundingSphere {
    glm::vec3 centre{0.0f};
    float radius = -1.0f; // < 0: empty (no triangles)
};

struct ObjectOccluder {
    scene::Bvh bvh;
    BoundingSphere bounds;
    // Every vertex lies on or below every triangle's plane, as its winding orients it (a closed
    // convex mesh seen from outside, a flat ground): a ray leaving a point of the mesh above its
    // triangle's plane cannot hit the mesh again, so the point needs no self-visibility rays (Õ1
    // is its horizon alone). `convexBack`: the same with the planes facing the other way (a
    // point seen from behind its triangle's winding; both for a flat mesh).
    bool convexFront = false;
    bool convexBack = false;
};



// Convexity of a mesh in its own space (ObjectOccluder::convexFront / convexBack before the
// object's transform: one with a positive determinant keeps both, a mirror swaps them). Cached
// per mesh by the preview: a drag moves the object, not its mesh.
struct MeshConvexity {
    bool front = false;
    bool back = false;
};
MeshConvexity meshConvexity(const scene::TriangleMesh& mesh);
using ConvexityCache = std::map<std::shared_ptr<const scene::TriangleMesh>, MeshConvexity>;

ObjectOccluder buildObjectOccluder(const scene::Scene& scene, size_t objectIndex, ConvexityCache& cache);

// The texels of `candidates` whose directions from p may meet the sphere (conservative: widened
// by the texel radius). Empty bits for an empty sphere.
TexelBits coneTexels(const BoundingSphere& sphere, const glm::vec3& p, const TexelDirections& dirs,
                     const TexelBits& candidates);

// Bit t set where the ray from `origin` along texel t's centre direction hits the occluder, for
// the texels set in `candidates` only.
TexelBits castOcclusion(const ObjectOccluder& occluder, const glm::vec3& origin,
                        const TexelDirections& dirs, const TexelBits& candidates);

} // namespace wavelit::relight
