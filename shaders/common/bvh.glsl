// Software BVH traversal (lavapipe has no ray queries): the layout of renderer/scene/bvh.h and the
// same slab test and Moller-Trumbore arithmetic as bvh.cpp's CPU traversal, nearer child first
// with a fixed stack. The including shader declares `bvhNodes64` and `bvhTriangles64`, the
// 64-bit views of common/packed64.glsl, and with WAVELIT_SCENE_TEXELS_BINDING their texel views
// `bvhNodeTexels` and `bvhTriangleTexels` (RGBA32UI), which the traversal then reads instead.
#ifndef WAVELIT_BVH_GLSL
#define WAVELIT_BVH_GLSL

#include "common/constants.glsl"

// 64 entries cover a tree of depth 64; binned SAH trees over millions of triangles stay far below.
#define BVH_STACK_SIZE 64

// The box test of `node`, read as one u64vec4 (common/packed64.glsl); info = (leftFirst, count)
// from the same load, so a node the traversal descends into is not read again.
float bvhHitBox(uint node, vec3 o, vec3 invDir, float tMin, float tMax, out uvec2 info) {
#ifdef WAVELIT_SCENE_TEXELS_BINDING
    // A node is two RGBA32UI texels: (min, leftFirst), (max, count).
    uvec4 lo = texelFetch(bvhNodeTexels, int(2u * node));
    uvec4 hi = texelFetch(bvhNodeTexels, int(2u * node + 1u));
    info = uvec2(lo.w, hi.w);
    vec3 t0 = (uintBitsToFloat(lo.xyz) - o) * invDir;
    vec3 t1 = (uintBitsToFloat(hi.xyz) - o) * invDir;
#else
    u64vec4 q = bvhNodes64[node].q;
    vec2 minZ = words2(q.y), maxZ = words2(q.w);
    info = uvec2(highWord(q.y), highWord(q.w));
    vec3 t0 = (vec3(words2(q.x), minZ.x) - o) * invDir;
    vec3 t1 = (vec3(words2(q.z), maxZ.x) - o) * invDir;
#endif
    vec3 tn = min(t0, t1), tf = max(t0, t1);
    float enter = max(max(tn.x, tn.y), max(tn.z, tMin));
    float exit = min(min(tf.x, tf.y), min(tf.z, tMax));
    return enter <= exit ? enter : kInfinity;
}

bool bvhHitTriangle(uint i, vec3 o, vec3 d, float tMin, float tMax, out float t, out float b1,
                    out float b2) {
#ifdef WAVELIT_SCENE_TEXELS_BINDING
    // A triangle is six texels (v0, v1, v2, n0, n1, n2); the test reads the first three.
    vec3 v0 = uintBitsToFloat(texelFetch(bvhTriangleTexels, int(6u * i)).xyz);
    vec3 e1 = uintBitsToFloat(texelFetch(bvhTriangleTexels, int(6u * i + 1u)).xyz) - v0;
    vec3 e2 = uintBitsToFloat(texelFetch(bvhTriangleTexels, int(6u * i + 2u)).xyz) - v0;
#else
    // Three 64-bit pairs (6 loads a lane) instead of three vec3s (9).
    u64vec2 w0 = bvhTriangles64[i].v0, w1 = bvhTriangles64[i].v1, w2 = bvhTriangles64[i].v2;
    vec3 v0 = vec3(words2(w0.x), words2(w0.y).x);
    vec3 e1 = vec3(words2(w1.x), words2(w1.y).x) - v0;
    vec3 e2 = vec3(words2(w2.x), words2(w2.y).x) - v0;
#endif
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
    bool found = false;
    uvec2 info; // the current node's (leftFirst, count)
    if (bvhHitBox(0u, o, invDir, tMin, tMax, info) == kInfinity) return false;
    for (;;) {
        uint first = info.x, count = info.y;
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
            uvec2 infoA, infoB;
            float ta = bvhHitBox(a, o, invDir, tMin, tMax, infoA);
            float tb = bvhHitBox(b, o, invDir, tMin, tMax, infoB);
            if (ta > tb) {
                float tt = ta; ta = tb; tb = tt;
                uint tn = a; a = b; b = tn;
                infoA = infoB;
            }
            if (ta != kInfinity) {
                if (tb != kInfinity && sp < BVH_STACK_SIZE) {
                    stack[sp] = b;
                    stackEnter[sp] = tb;
                    ++sp;
                }
                info = infoA;
                descended = true;
            }
        }
        if (descended) continue;
        // Pop, skipping nodes whose box now lies beyond the closest hit (the stored entry
        // distance against the shrunken tMax is the box test redone, as in bvh.cpp).
        bool popped = false;
        uint node = 0u;
        while (sp > 0) {
            --sp;
            node = stack[sp];
            if (stackEnter[sp] <= tMax) {
                popped = true;
                break;
            }
        }
        if (!popped) return found;
#ifdef WAVELIT_SCENE_TEXELS_BINDING
        info = uvec2(texelFetch(bvhNodeTexels, int(2u * node)).w,
                     texelFetch(bvhNodeTexels, int(2u * node + 1u)).w);
#else
        uint64_t q1 = bvhNodes64[node].q.y, q3 = bvhNodes64[node].q.w;
        info = uvec2(highWord(q1), highWord(q3));
#endif
    }
    return found;
}

#endif
