// BVH traversal against brute force over every triangle: random soups and a structured mesh,
// random rays from inside and outside; closest hits must agree exactly (same triangle test).
#include "scene/bvh.h"

#include "util/rng.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <memory>

namespace wavelit::scene {
namespace {

// Brute-force closest hit with the same Moller-Trumbore arithmetic as bvh.cpp.
bool bruteForce(const Bvh& bvh, glm::vec3 o, glm::vec3 d, float tMin, float tMax, BvhHit& hit) {
    bool found = false;
    for (uint32_t i = 0; i < bvh.triangles.size(); ++i) {
        const BvhTriangle& tri = bvh.triangles[i];
        glm::vec3 v0(tri.v0[0], tri.v0[1], tri.v0[2]);
        glm::vec3 e1 = glm::vec3(tri.v1[0], tri.v1[1], tri.v1[2]) - v0;
        glm::vec3 e2 = glm::vec3(tri.v2[0], tri.v2[1], tri.v2[2]) - v0;
        glm::vec3 p = glm::cross(d, e2);
        float det = glm::dot(e1, p);
        if (det == 0.0f)
            continue;
        float inv = 1.0f / det;
        glm::vec3 s = o - v0;
        float u = glm::dot(s, p) * inv;
        if (u < 0.0f || u > 1.0f)
            continue;
        glm::vec3 q = glm::cross(s, e1);
        float v = glm::dot(d, q) * inv;
        if (v < 0.0f || u + v > 1.0f)
            continue;
        float t = glm::dot(e2, q) * inv;
        if (!(t > tMin && t < tMax))
            continue;
        tMax = t;
        hit = BvhHit{t, i, u, v};
        found = true;
    }
    return found;
}

glm::vec3 randomVec(util::Pcg32& rng, float lo, float hi) {
    return glm::vec3(lo + (hi - lo) * rng.nextFloat(), lo + (hi - lo) * rng.nextFloat(),
                     lo + (hi - lo) * rng.nextFloat());
}

Scene soupScene(int triangles, uint64_t seed) {
    util::Pcg32 rng(seed);
    auto mesh = std::make_shared<TriangleMesh>();
    for (int i = 0; i < triangles; ++i) {
        glm::vec3 c = randomVec(rng, -5.0f, 5.0f);
        for (int k = 0; k < 3; ++k) {
            mesh->positions.push_back(c + randomVec(rng, -0.6f, 0.6f));
            mesh->indices.push_back(uint32_t(mesh->positions.size() - 1));
        }
    }
    Scene scene;
    Material mat;
    mat.id = 1;
    scene.materials.push_back(mat);
    Object obj;
    obj.id = 2;
    obj.materialId = 1;
    obj.mesh = mesh;
    obj.transform.translation = glm::vec3(0.5f, -0.25f, 0.0f);
    obj.transform.rotationDeg = glm::vec3(10.0f, 20.0f, 30.0f);
    scene.objects.push_back(obj);
    return scene;
}

void compareRandomRays(const Bvh& bvh, uint64_t seed, int rays, int minHits) {
    util::Pcg32 rng(seed);
    int hits = 0;
    for (int r = 0; r < rays; ++r) {
        glm::vec3 o = randomVec(rng, -8.0f, 8.0f);
        glm::vec3 d = glm::normalize(randomVec(rng, -1.0f, 1.0f));
        // Aim half the rays at the middle so many of them hit.
        if (r % 2 == 0)
            d = glm::normalize(randomVec(rng, -2.0f, 2.0f) - o);
        BvhHit expected, got;
        bool e = bruteForce(bvh, o, d, 1e-4f, std::numeric_limits<float>::max(), expected);
        bool g = intersect(bvh, o, d, 1e-4f, std::numeric_limits<float>::max(), got);
        ASSERT_EQ(e, g) << "ray " << r;
        EXPECT_EQ(occluded(bvh, o, d, 1e-4f, std::numeric_limits<float>::max()), e) << "ray " << r;
        if (e) {
            ++hits;
            // Same arithmetic per triangle, so the closest distance is bit-identical.
            EXPECT_EQ(expected.t, got.t) << "ray " << r;
            EXPECT_EQ(expected.b1, got.b1);
            EXPECT_EQ(expected.b2, got.b2);
            // A bounded occlusion query stops before the hit.
            EXPECT_FALSE(occluded(bvh, o, d, 1e-4f, expected.t * 0.999f)) << "ray " << r;
        }
    }
    EXPECT_GE(hits, minHits); // the test exercises hits, not only misses
}

void checkStructure(const Bvh& bvh) {
    // Every triangle is referenced by exactly one leaf, and leaves lie inside their boxes.
    std::vector<int> seen(bvh.triangles.size(), 0);
    for (const BvhNode& n : bvh.nodes) {
        if (n.count == 0) {
            ASSERT_LT(n.leftFirst + 1, bvh.nodes.size());
            continue;
        }
        for (uint32_t i = n.leftFirst; i < n.leftFirst + n.count; ++i) {
            ++seen[i];
            for (const float* v : {bvh.triangles[i].v0, bvh.triangles[i].v1, bvh.triangles[i].v2})
                for (int k = 0; k < 3; ++k) {
                    EXPECT_GE(v[k], n.boundsMin[k]);
                    EXPECT_LE(v[k], n.boundsMax[k]);
                }
        }
    }
    for (int s : seen)
        EXPECT_EQ(s, 1);
}

TEST(Bvh, RandomSoupMatchesBruteForce) {
    for (int count : {1, 7, 300, 3000}) {
        Bvh bvh = buildBvh(soupScene(count, 17 + count));
        ASSERT_EQ(bvh.triangles.size(), size_t(count));
        checkStructure(bvh);
        compareRandomRays(bvh, 99 + count, 2000, count >= 300 ? 200 : 0);
    }
}

TEST(Bvh, SkipsDegenerateTrianglesAndCarriesIndices) {
    Scene scene = soupScene(10, 5);
    auto mesh = std::make_shared<TriangleMesh>(*scene.objects[0].mesh);
    mesh->positions.push_back(glm::vec3(1, 1, 1));
    mesh->positions.push_back(glm::vec3(2, 2, 2));
    mesh->positions.push_back(glm::vec3(1, 1, 1)); // repeated vertex: exactly zero area
    for (uint32_t k = 0; k < 3; ++k)
        mesh->indices.push_back(uint32_t(mesh->positions.size() - 3 + k));
    scene.objects[0].mesh = mesh;
    Object second = scene.objects[0];
    second.id = 3;
    second.materialId = 42; // unknown: default material index = materials.size()
    scene.objects.push_back(second);
    Bvh bvh = buildBvh(scene);
    EXPECT_EQ(bvh.triangles.size(), 20u);
    int perObject[2] = {0, 0};
    for (const BvhTriangle& t : bvh.triangles) {
        int obj = int(t.v1[3]);
        ASSERT_TRUE(obj == 0 || obj == 1);
        ++perObject[obj];
        EXPECT_EQ(t.v0[3], obj == 0 ? 0.0f : 1.0f);
        // Without vertex normals, the stored normals are the unit geometric normal.
        EXPECT_NEAR(std::sqrt(t.n0[0] * t.n0[0] + t.n0[1] * t.n0[1] + t.n0[2] * t.n0[2]), 1.0f,
                    1e-5f);
    }
    EXPECT_EQ(perObject[0], 10);
    EXPECT_EQ(perObject[1], 10);
}

TEST(Bvh, EmptySceneNeverHits) {
    Bvh bvh = buildBvh(Scene{});
    ASSERT_EQ(bvh.nodes.size(), 1u);
    BvhHit hit;
    EXPECT_FALSE(intersect(bvh, glm::vec3(0), glm::vec3(0, 0, 1), 0.0f, 1e30f, hit));
    EXPECT_FALSE(occluded(bvh, glm::vec3(0), glm::vec3(0, 0, 1), 0.0f, 1e30f));
}

TEST(Bvh, GridOfCoplanarTrianglesSplitsIntoSmallLeaves) {
    // A flat 40x40 quad grid: all centroids in one plane, a degenerate axis for the binning.
    auto mesh = std::make_shared<TriangleMesh>();
    const int n = 40;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            mesh->positions.push_back(glm::vec3(i * 0.1f, 0.0f, j * 0.1f));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            for (uint32_t v : {a, c, b, b, c, d})
                mesh->indices.push_back(v);
        }
    Scene scene;
    Object obj;
    obj.mesh = mesh;
    scene.objects.push_back(obj);
    Bvh bvh = buildBvh(scene);
    checkStructure(bvh);
    uint32_t largestLeaf = 0;
    for (const BvhNode& node : bvh.nodes)
        largestLeaf = std::max(largestLeaf, node.count);
    EXPECT_LE(largestLeaf, 8u);
    compareRandomRays(bvh, 3, 1000, 50);
}

} // namespace
} // namespace wavelit::scene
