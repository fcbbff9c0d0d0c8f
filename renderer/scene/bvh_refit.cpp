#include "scene/bvh_refit.h"

#include "util/timer.h"

#include <glm/common.hpp>

#include <algorithm>
#include <limits>

namespace wavelit::scene {
namespace {

struct Box {
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{-std::numeric_limits<float>::max()};
    void grow(const float* p) {
        lo = glm::min(lo, glm::vec3(p[0], p[1], p[2]));
        hi = glm::max(hi, glm::vec3(p[0], p[1], p[2]));
    }
};

void setBounds(BvhNode& n, const Box& b) {
    for (int k = 0; k < 3; ++k) {
        n.boundsMin[k] = b.lo[k];
        n.boundsMax[k] = b.hi[k];
    }
}

} // namespace

bool refitObjects(Bvh& bvh, const Scene& scene, const std::vector<size_t>& objectIndices) {
    util::Timer timer;
    if (bvh.meshTriangles.size() != bvh.triangles.size())
        return false;
    for (size_t objIndex : objectIndices) {
        if (objIndex >= scene.objects.size())
            return false;
        // The object's new triangles by mesh index; a slot stays empty for a degenerate one.
        const std::vector<ObjectTriangle> fresh = objectTriangles(scene, objIndex);
        const size_t meshTris = scene.objects[objIndex].mesh ? scene.objects[objIndex].mesh->triangleCount() : 0;
        std::vector<const BvhTriangle*> byMesh(meshTris, nullptr);
        for (const ObjectTriangle& t : fresh)
            byMesh[t.meshTriangle] = &t.triangle;
        size_t matched = 0;
        for (size_t i = 0; i < bvh.triangles.size(); ++i) {
            if (uint32_t(bvh.triangles[i].v1[3]) != objIndex)
                continue;
            const uint32_t m = bvh.meshTriangles[i];
            if (m >= byMesh.size() || !byMesh[m])
                return false;
            bvh.triangles[i] = *byMesh[m];
            ++matched;
        }
        if (matched != fresh.size())
            return false; // a triangle that was degenerate is not: the tree lacks it
    }
    // Children are always stored after their parent (the builder appends them), so one pass
    // from the last node to the root sees every child before its parent.
    if (bvh.triangles.empty())
        return true;
    for (size_t k = bvh.nodes.size(); k-- > 0;) {
        BvhNode& n = bvh.nodes[k];
        Box box;
        if (n.count > 0) {
            for (uint32_t i = n.leftFirst; i < n.leftFirst + n.count; ++i) {
                box.grow(bvh.triangles[i].v0);
                box.grow(bvh.triangles[i].v1);
                box.grow(bvh.triangles[i].v2);
            }
        } else {
            for (const BvhNode* c : {&bvh.nodes[n.leftFirst], &bvh.nodes[n.leftFirst + 1]}) {
                box.grow(c->boundsMin);
                box.grow(c->boundsMax);
            }
        }
        setBounds(n, box);
    }
    bvh.buildSeconds = timer.seconds();
    return true;
}

} // namespace wavelit::scene
