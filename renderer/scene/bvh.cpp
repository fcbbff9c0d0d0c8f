// Binned-SAH BVH build (Wald 2007, "On fast construction of SAH-based BVHs") and the CPU
// traversal. The shader (shaders/common/bvh.glsl) walks the same flattened arrays with the same
// slab test and Moller-Trumbore intersection, so both tracers see the same geometry.
//
// Trade-offs: 16 bins per axis is within a few percent of a full sweep for our meshes and keeps
// the build O(n log n) with small constants; leaves hold at most kMaxLeafSize triangles so the
// GPU's per-leaf loop stays short.
#include "scene/bvh.h"

#include "util/timer.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace wavelit::scene {
namespace {

constexpr int kBins = 16;
constexpr uint32_t kMaxLeafSize = 4;
// Cost of one traversal step relative to one triangle test (typical SAH constant).
constexpr float kTraversalCost = 1.0f;

struct Aabb {
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{-std::numeric_limits<float>::max()};
    void grow(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void grow(const Aabb& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool empty() const { return lo.x > hi.x; }
    float area() const {
        if (empty())
            return 0.0f;
        glm::vec3 e = hi - lo;
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
};

struct BuildPrim {
    Aabb box;
    glm::vec3 centroid;
};

class Builder {
public:
    Builder(const std::vector<BuildPrim>& prims, std::vector<uint32_t>& order,
            std::vector<BvhNode>& nodes)
        : m_prims(prims), m_order(order), m_nodes(nodes) {}

    // Builds the subtree of order[first, first + count) into nodes[index].
    void build(uint32_t index, uint32_t first, uint32_t count) {
        Aabb box, centroidBox;
        for (uint32_t i = first; i < first + count; ++i) {
            box.grow(m_prims[m_order[i]].box);
            centroidBox.grow(m_prims[m_order[i]].centroid);
        }
        setBounds(index, box);
        if (count <= kMaxLeafSize || !split(index, first, count, box, centroidBox))
            makeLeaf(index, first, count);
    }

private:
    void setBounds(uint32_t index, const Aabb& box) {
        BvhNode& n = m_nodes[index];
        for (int k = 0; k < 3; ++k) {
            n.boundsMin[k] = box.lo[k];
            n.boundsMax[k] = box.hi[k];
        }
    }
    void makeLeaf(uint32_t index, uint32_t first, uint32_t count) {
        m_nodes[index].leftFirst = first;
        m_nodes[index].count = count;
    }

    // Returns false when no split beats a leaf (then the caller makes one, unless it is too
    // large, in which case a median split guarantees termination).
    bool split(uint32_t index, uint32_t first, uint32_t count, const Aabb& box,
               const Aabb& centroidBox) {
        float bestCost = std::numeric_limits<float>::max();
        int bestAxis = -1, bestBin = -1;
        for (int axis = 0; axis < 3; ++axis) {
            float lo = centroidBox.lo[axis], hi = centroidBox.hi[axis];
            if (!(hi > lo))
                continue;
            std::array<Aabb, kBins> bins;
            std::array<uint32_t, kBins> counts{};
            float scale = kBins / (hi - lo);
            for (uint32_t i = first; i < first + count; ++i) {
                const BuildPrim& p = m_prims[m_order[i]];
                int b = std::min(kBins - 1, int((p.centroid[axis] - lo) * scale));
                bins[b].grow(p.box);
                ++counts[b];
            }
            // Sweep from the right for suffix areas, then from the left.
            std::array<float, kBins> rightArea{};
            std::array<uint32_t, kBins> rightCount{};
            Aabb acc;
            uint32_t n = 0;
            for (int b = kBins - 1; b > 0; --b) {
                acc.grow(bins[b]);
                n += counts[b];
                rightArea[b] = acc.area();
                rightCount[b] = n;
            }
            acc = Aabb{};
            n = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                acc.grow(bins[b]);
                n += counts[b];
                if (n == 0 || rightCount[b + 1] == 0)
                    continue;
                float cost = acc.area() * float(n) + rightArea[b + 1] * float(rightCount[b + 1]);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBin = b;
                }
            }
        }
        float leafCost = box.area() * float(count);
        float parentArea = box.area();
        bool sahSplit =
            bestAxis >= 0 && (kTraversalCost * parentArea + bestCost < leafCost || count > 64);
        uint32_t mid;
        if (sahSplit) {
            float lo = centroidBox.lo[bestAxis];
            float scale = kBins / (centroidBox.hi[bestAxis] - lo);
            auto it = std::partition(
                m_order.begin() + first, m_order.begin() + first + count, [&](uint32_t i) {
                    int b = std::min(kBins - 1, int((m_prims[i].centroid[bestAxis] - lo) * scale));
                    return b <= bestBin;
                });
            mid = uint32_t(it - m_order.begin());
        } else if (bestAxis < 0 && count > kMaxLeafSize * 4) {
            // All centroids coincide: split by index so leaves stay bounded.
            mid = first + count / 2;
        } else {
            return false;
        }
        if (mid == first || mid == first + count)
            mid = first + count / 2;
        uint32_t left = uint32_t(m_nodes.size());
        m_nodes.resize(m_nodes.size() + 2);
        m_nodes[index].leftFirst = left;
        m_nodes[index].count = 0;
        build(left, first, mid - first);
        build(left + 1, mid, first + count - mid);
        return true;
    }

    const std::vector<BuildPrim>& m_prims;
    std::vector<uint32_t>& m_order;
    std::vector<BvhNode>& m_nodes;
};

void setVec4(float* dst, const glm::vec3& v, float w) {
    dst[0] = v.x;
    dst[1] = v.y;
    dst[2] = v.z;
    dst[3] = w;
}

glm::vec3 vec3Of(const float* v) {
    return {v[0], v[1], v[2]};
}

// Slab test; returns the entry distance or +inf when the box is missed in (tMin, tMax). Inlined
// into the traversal, where a node's two child tests interleave: as a call it was ~20% of a C++
// pass (docs/performance.md).
[[gnu::always_inline]] inline float hitBox(const BvhNode& n, const glm::vec3& o,
                                           const glm::vec3& invDir, float tMin, float tMax) {
    glm::vec3 t0 = (vec3Of(n.boundsMin) - o) * invDir;
    glm::vec3 t1 = (vec3Of(n.boundsMax) - o) * invDir;
    glm::vec3 tn = glm::min(t0, t1), tf = glm::max(t0, t1);
    float enter = std::max(std::max(tn.x, tn.y), std::max(tn.z, tMin));
    float exit = std::min(std::min(tf.x, tf.y), std::min(tf.z, tMax));
    return enter <= exit ? enter : std::numeric_limits<float>::infinity();
}

// Moller-Trumbore; the shader uses the identical arithmetic.
bool hitTriangle(const BvhTriangle& tri, const glm::vec3& o, const glm::vec3& d, float tMin,
                 float tMax, float& t, float& b1, float& b2) {
    glm::vec3 v0 = vec3Of(tri.v0), e1 = vec3Of(tri.v1) - v0, e2 = vec3Of(tri.v2) - v0;
    glm::vec3 p = glm::cross(d, e2);
    float det = glm::dot(e1, p);
    if (det == 0.0f)
        return false;
    float inv = 1.0f / det;
    glm::vec3 s = o - v0;
    float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f)
        return false;
    glm::vec3 q = glm::cross(s, e1);
    float v = glm::dot(d, q) * inv;
    if (v < 0.0f || u + v > 1.0f)
        return false;
    float tt = glm::dot(e2, q) * inv;
    if (!(tt > tMin && tt < tMax))
        return false;
    t = tt;
    b1 = u;
    b2 = v;
    return true;
}

constexpr int kStackSize = 64;

template <bool AnyHit>
bool traverse(const Bvh& bvh, const glm::vec3& o, const glm::vec3& d, float tMin, float tMax,
              BvhHit* hit) {
    // An empty scene's root is an interior node without children: never descend into it.
    if (bvh.nodes.empty() || bvh.triangles.empty())
        return false;
    glm::vec3 invDir = 1.0f / d;
    uint32_t stack[kStackSize];
    float stackEnter[kStackSize]; // entry distance of each stacked box
    int sp = 0;
    uint32_t node = 0;
    bool found = false;
    if (hitBox(bvh.nodes[0], o, invDir, tMin, tMax) == std::numeric_limits<float>::infinity())
        return false;
    for (;;) {
        const BvhNode& n = bvh.nodes[node];
        if (n.count > 0) {
            for (uint32_t i = n.leftFirst; i < n.leftFirst + n.count; ++i) {
                float t, b1, b2;
                if (hitTriangle(bvh.triangles[i], o, d, tMin, tMax, t, b1, b2)) {
                    if (AnyHit)
                        return true;
                    found = true;
                    tMax = t;
                    *hit = BvhHit{t, i, b1, b2};
                }
            }
        } else {
            uint32_t a = n.leftFirst, b = n.leftFirst + 1;
            float ta = hitBox(bvh.nodes[a], o, invDir, tMin, tMax);
            float tb = hitBox(bvh.nodes[b], o, invDir, tMin, tMax);
            if (ta > tb) {
                std::swap(ta, tb);
                std::swap(a, b);
            }
            constexpr float kInf = std::numeric_limits<float>::infinity();
            if (ta != kInf) {
                if (tb != kInf && sp < kStackSize) {
                    stack[sp] = b;
                    stackEnter[sp++] = tb;
                }
                node = a;
                continue;
            }
        }
        // Pop, skipping nodes whose box is now farther than the closest hit. Comparing the
        // entry distance stored at push time with the shrunken tMax is exactly the box test
        // redone (its exit side was already passed), without reloading the box.
        for (;;) {
            if (sp == 0)
                return found;
            --sp;
            node = stack[sp];
            if (stackEnter[sp] <= tMax)
                break;
        }
    }
}

} // namespace

std::vector<ObjectTriangle> objectTriangles(const Scene& scene, size_t objIndex) {
    std::vector<ObjectTriangle> out;
    const Object& obj = scene.objects[objIndex];
    if (!obj.mesh)
        return out;
    const TriangleMesh& mesh = *obj.mesh;
    glm::mat4 m = obj.transform.matrix();
    glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
    // Objects without a known material get index materials.size(): the default material.
    float material = float(scene.materials.size());
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].id == obj.materialId)
            material = float(i);
    bool hasNormals = mesh.normals.size() == mesh.positions.size();
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        uint32_t idx[3] = {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
        if (idx[0] >= mesh.positions.size() || idx[1] >= mesh.positions.size() ||
            idx[2] >= mesh.positions.size())
            continue;
        glm::vec3 p[3], n[3];
        for (int k = 0; k < 3; ++k)
            p[k] = glm::vec3(m * glm::vec4(mesh.positions[idx[k]], 1.0f));
        glm::vec3 ng = glm::cross(p[1] - p[0], p[2] - p[0]);
        float len = glm::length(ng);
        if (!(len > 0.0f) || !std::isfinite(len))
            continue; // degenerate
        ng /= len;
        for (int k = 0; k < 3; ++k) {
            n[k] = ng;
            if (hasNormals) {
                glm::vec3 sn = normalMatrix * mesh.normals[idx[k]];
                float sl = glm::length(sn);
                if (sl > 0.0f && std::isfinite(sl))
                    n[k] = sn / sl;
            }
        }
        BvhTriangle tri{};
        setVec4(tri.v0, p[0], material);
        setVec4(tri.v1, p[1], float(objIndex));
        setVec4(tri.v2, p[2], 0.0f);
        setVec4(tri.n0, n[0], 0.0f);
        setVec4(tri.n1, n[1], 0.0f);
        setVec4(tri.n2, n[2], 0.0f);
        out.push_back({uint32_t(t), tri});
    }
    return out;
}

Bvh buildBvh(const Scene& scene) {
    util::Timer timer;
    Bvh bvh;
    std::vector<BvhTriangle> tris;
    std::vector<uint32_t> source;
    for (size_t objIndex = 0; objIndex < scene.objects.size(); ++objIndex)
        for (const ObjectTriangle& t : objectTriangles(scene, objIndex)) {
            tris.push_back(t.triangle);
            source.push_back(t.meshTriangle);
        }

    std::vector<BuildPrim> prims(tris.size());
    for (size_t i = 0; i < tris.size(); ++i) {
        Aabb b;
        b.grow(vec3Of(tris[i].v0));
        b.grow(vec3Of(tris[i].v1));
        b.grow(vec3Of(tris[i].v2));
        prims[i] = BuildPrim{b, 0.5f * (b.lo + b.hi)};
    }
    std::vector<uint32_t> order(tris.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = uint32_t(i);

    bvh.nodes.reserve(tris.empty() ? 1 : 2 * tris.size());
    bvh.nodes.resize(1);
    if (tris.empty()) {
        // A single node without triangles; traversal checks the triangle count first.
        bvh.nodes[0] = BvhNode{{1, 1, 1}, 0, {-1, -1, -1}, 0};
    } else {
        Builder(prims, order, bvh.nodes).build(0, 0, uint32_t(tris.size()));
    }
    bvh.triangles.resize(tris.size());
    bvh.meshTriangles.resize(tris.size());
    for (size_t i = 0; i < order.size(); ++i) {
        bvh.triangles[i] = tris[order[i]];
        bvh.meshTriangles[i] = source[order[i]];
    }
    bvh.builtSahCost = bvhSahCost(bvh);
    bvh.buildSeconds = timer.seconds();
    return bvh;
}

float bvhSahCost(const Bvh& bvh) {
    auto area = [](const BvhNode& n) {
        const glm::vec3 e = glm::max(vec3Of(n.boundsMax) - vec3Of(n.boundsMin), glm::vec3(0.0f));
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    };
    if (bvh.triangles.empty() || !(area(bvh.nodes[0]) > 0.0f))
        return 0.0f;
    double cost = 0.0;
    for (const BvhNode& n : bvh.nodes)
        cost += double(area(n)) * (n.count > 0 ? double(n.count) : kTraversalCost);
    return float(cost / double(area(bvh.nodes[0])));
}

bool intersect(const Bvh& bvh, const glm::vec3& origin, const glm::vec3& dir, float tMin,
               float tMax, BvhHit& hit) {
    return traverse<false>(bvh, origin, dir, tMin, tMax, &hit);
}

bool occluded(const Bvh& bvh, const glm::vec3& origin, const glm::vec3& dir, float tMin,
              float tMax) {
    return traverse<true>(bvh, origin, dir, tMin, tMax, nullptr);
}

} // namespace wavelit::scene
