// Software BVH traversal (lavapipe has no ray queries): the layout of renderer/scene/bvh.h and the
// same slab test and Moller-Trumbore arithmetic as bvh.cpp's CPU traversal, nearer child first
// with a fixed stack. The including shader declares `bvhNodes` and `bvhTriangles`.
#ifndef WAVELIT_BVH_GLSL
#define WAVELIT_BVH_GLSL

#include "common/constants.glsl"

// 64 entries cover a tree of depth 64; binned SAH trees over millions of triangles stay far below.
#define BVH_STACK_SIZE 64

float bvhHitBox(uint node, vec3 o, vec3 invDir, float tMin, float tMax) {
    vec3 t0 = (bvhNodes[node].boundsMin - o) * invDir;
    vec3 t1 = (bvhNodes[node].boundsMax - o) * invDir;
    vec3 tn = min(t0, t1), tf = max(t0, t1);
    float enter = max(max(tn.x, tn.y), max(tn.z, tMin));
    float exit = min(min(tf.x, tf.y), min(tf.z, tMax));
    return enter <= exit ? enter : kInfinity;
}

bool bvhHitTriangle(uint i, vec3 o, vec3 d, float tMin, float tMax, out float t, out float b1,
                    out float b2) {
    vec3 v0 = bvhTriangles[i].v0.xyz;
    vec3 e1 = bvhTriangles[i].v1.xyz - v0, e2 = bvhTriangles[i].v2.xyz - v0;
    vec3 p = cross(d, e2);
    float det = dot(e1, p);
    t = 0.0;
    b1 = 0.0;
    b2 = 0.0;
    if (det == 0.0) return false;
    float inv = 1.0 / det;
    vec3 s = o - v0;
    float u = dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return false;
    vec3 q = cross(s, e1);
    float v = dot(d, q) * inv;
    if (v < 0.0 || u + v > 1.0) return false;
    float tt = dot(e2, q) * inv;
    if (!(tt > tMin && tt < tMax)) return false;
    t = tt;
    b1 = u;
    b2 = v;
    return true;
}

// Closest hit (anyHit = false) or any hit (shadow rays). triangleCount 0 = empty scene.
bool bvhTrace(vec3 o, vec3 d, float tMin, float tMax, bool anyHit, uint triangleCount,
              out uint hitTri, out float hitT, out float hitB1, out float hitB2) {
    hitTri = 0u;
    hitT = 0.0;
    hitB1 = 0.0;
    hitB2 = 0.0;
    if (triangleCount == 0u) return false;
    vec3 invDir = 1.0 / d;
    uint stack[BVH_STACK_SIZE];
    float stackEnter[BVH_STACK_SIZE];
    int sp = 0;
    uint node = 0u;
    bool found = false;
    if (bvhHitBox(0u, o, invDir, tMin, tMax) == kInfinity) return false;
    for (;;) {
        uint count = bvhNodes[node].count;
        uint first = bvhNodes[node].leftFirst;
        bool descended = false;
        if (count > 0u) {
            for (uint i = first; i < first + count; ++i) {
                float t, b1, b2;
                if (bvhHitTriangle(i, o, d, tMin, tMax, t, b1, b2)) {
                    if (anyHit) return true;
                    found = true;
                    tMax = t;
                    hitTri = i;
                    hitT = t;
                    hitB1 = b1;
                    hitB2 = b2;
                }
            }
        } else {
            uint a = first, b = first + 1u;
            float ta = bvhHitBox(a, o, invDir, tMin, tMax);
            float tb = bvhHitBox(b, o, invDir, tMin, tMax);
            if (ta > tb) {
                float tt = ta; ta = tb; tb = tt;
                uint tn = a; a = b; b = tn;
            }
            if (ta != kInfinity) {
                if (tb != kInfinity && sp < BVH_STACK_SIZE) {
                    stack[sp] = b;
                    stackEnter[sp] = tb;
                    ++sp;
                }
                node = a;
                descended = true;
            }
        }
        if (descended) continue;
        // Pop, skipping nodes whose box now lies beyond the closest hit (the stored entry
        // distance against the shrunken tMax is the box test redone, as in bvh.cpp).
        bool popped = false;
        while (sp > 0) {
            --sp;
            node = stack[sp];
            if (stackEnter[sp] <= tMax) {
                popped = true;
                break;
            }
        }
        if (!popped) return found;
    }
    return found;
}

#endif
