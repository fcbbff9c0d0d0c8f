// refitObjects against a fresh build: after an object moves (or changes material), the refitted
// BVH must find the same closest hits, bit for bit, as buildBvh on the edited scene, and every
// triangle must lie inside its leaf's box; a refit that cannot match the scene says so.
#include "scene/bvh_refit.h"

#include "util/rng.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <limits>
#include <memory>

namespace wavelit::scene {
namespace {

glm::vec3 randomVec(util::Pcg32& rng, float lo, float hi) {
    return glm::vec3(lo + (hi - lo) * rng.nextFloat(), lo + (hi - lo) * rng.nextFloat(),
                     lo + (hi - lo) * rng.nextFloat());
}

std::shared_ptr<TriangleMesh> soup(int triangles, uint64_t seed) {
    util::Pcg32 rng(seed);
    auto mesh = std::make_shared<TriangleMesh>();
    for (int i = 0; i < triangles; ++i) {
        glm::vec3 c = randomVec(rng, -2.0f, 2.0f);
        for (int k = 0; k < 3; ++k) {
            mesh->positions.push_back(c + randomVec(rng, -0.4f, 0.4f));
            mesh->indices.push_back(uint32_t(mesh->positions.size() - 1));
        }
    }
    return mesh;
}

Scene twoObjects() {
    Scene scene;
    for (EntityId id : {1u, 2u}) {
        Material m;
        m.id = id;
        scene.materials.push_back(m);
    }
    for (EntityId id : {3u, 4u}) {
        Object o;
        o.id = id;
        o.materialId = 1;
        o.mesh = soup(300, id);
        o.transform.translation = glm::vec3(id == 3 ? -2.0f : 2.0f, 0.0f, 0.0f);
        scene.objects.push_back(o);
    }
    return scene;
}

const float* vertexOf(const Bvh& bvh, const BvhHit& hit) { return bvh.triangles[hit.triangle].v0; }

void expectSameHits(const Bvh& refitted, const Bvh& fresh, uint64_t seed) {
    util::Pcg32 rng(seed);
    int hits = 0;
    for (int r = 0; r < 2000; ++r) {
        glm::vec3 o = randomVec(rng, -8.0f, 8.0f);
        glm::vec3 d = glm::normalize(randomVec(rng, -3.0f, 3.0f) - o);
        BvhHit a, b;
        const float far = std::numeric_limits<float>::max();
        const bool ha = intersect(refitted, o, d, 1e-4f, far, a);
        ASSERT_EQ(ha, intersect(fresh, o, d, 1e-4f, far, b)) << "ray " << r;
        EXPECT_EQ(occluded(refitted, o, d, 1e-4f, far), ha);
        if (!ha)
            continue;
        ++hits;
        EXPECT_EQ(a.t, b.t) << "ray " << r;
        EXPECT_EQ(a.b1, b.b1);
        EXPECT_EQ(a.b2, b.b2);
        for (int k = 0; k < 4; ++k) // same vertex, same material index (v0.w)
            EXPECT_EQ(vertexOf(refitted, a)[k], vertexOf(fresh, b)[k]);
    }
    EXPECT_GT(hits, 500);
}

void expectInsideLeaves(const Bvh& bvh) {
    for (const BvhNode& n : bvh.nodes)
        for (uint32_t i = n.leftFirst; n.count > 0 && i < n.leftFirst + n.count; ++i)
            for (const float* v : {bvh.triangles[i].v0, bvh.triangles[i].v1, bvh.triangles[i].v2})
                for (int k = 0; k < 3; ++k) {
                    EXPECT_GE(v[k], n.boundsMin[k]);
                    EXPECT_LE(v[k], n.boundsMax[k]);
                }
}

TEST(BvhRefit, MovedObjectHitsAsAFreshBuild) {
    Scene scene = twoObjects();
    Bvh bvh = buildBvh(scene);
    ASSERT_EQ(bvh.meshTriangles.size(), bvh.triangles.size());
    scene.objects[0].transform.translation = glm::vec3(1.0f, 1.5f, -0.5f); // into the other one
    scene.objects[0].transform.rotationDeg = glm::vec3(0.0f, 45.0f, 10.0f);
    scene.objects[0].transform.scale = glm::vec3(1.5f, 0.5f, 1.0f);
    ASSERT_TRUE(refitObjects(bvh, scene, {0}));
    expectInsideLeaves(bvh);
    expectSameHits(bvh, buildBvh(scene), 7);
}

TEST(BvhRefit, MaterialChangeRewritesTheMaterialIndex) {
    Scene scene = twoObjects();
    Bvh bvh = buildBvh(scene);
    scene.objects[1].materialId = 2;
    ASSERT_TRUE(refitObjects(bvh, scene, {1}));
    int second = 0;
    for (const BvhTriangle& t : bvh.triangles)
        if (uint32_t(t.v1[3]) == 1) {
            EXPECT_EQ(t.v0[3], 1.0f);
            ++second;
        }
    EXPECT_EQ(second, 300);
    expectSameHits(bvh, buildBvh(scene), 8);
}

TEST(BvhRefit, FarMovesMakeTheTreeCostlierSmallOnesDoNot) {
    Scene scene = twoObjects();
    Bvh bvh = buildBvh(scene);
    ASSERT_GT(bvh.builtSahCost, 0.0f);
    EXPECT_EQ(bvhSahCost(bvh), bvh.builtSahCost);
    scene.objects[0].transform.translation.x += 0.05f;
    ASSERT_TRUE(refitObjects(bvh, scene, {0}));
    EXPECT_LT(bvhSahCost(bvh), 1.1f * bvh.builtSahCost);
    // Two objects built in the same place share subtrees; pulling one out of the other
    // stretches every shared box across the gap (what the session's rebuild threshold,
    // bvh_update.cpp, catches).
    scene.objects[0].transform.translation = scene.objects[1].transform.translation;
    Bvh mixed = buildBvh(scene);
    scene.objects[0].transform.translation.y += 6.0f;
    ASSERT_TRUE(refitObjects(mixed, scene, {0}));
    EXPECT_GT(bvhSahCost(mixed), 1.5f * mixed.builtSahCost);
    expectSameHits(mixed, buildBvh(scene), 9);
}

TEST(BvhRefit, RefusesAnotherMesh) {
    Scene scene = twoObjects();
    Bvh bvh = buildBvh(scene);
    scene.objects[0].mesh = soup(200, 99);
    EXPECT_FALSE(refitObjects(bvh, scene, {0}));
    EXPECT_FALSE(refitObjects(bvh, scene, {5}));
}

} // namespace
} // namespace wavelit::scene
