// The camera vertex's `wavelet` NEE mixture, cached per pixel across passes (issue 12,
// docs/performance.md "Wavelet pass cost, round 4"; render/gpu/product_cache.h packs the buffer).
// While an image accumulates, camera and scene are fixed, so the mixture a pixel's camera hit
// would build (its shares, product window and 2^m x 2^m pyramid: 289 BRDF x cos evaluations)
// is built ONCE, from the pixel centre's hit (jitter 0.5, 0.5), in the first pass after a reset
// (by the cache's own kernel: path_tracer.comp with WAVELIT_BUILD_PRODUCT_CACHE), and every pass
// draws from and evaluates the pdf of that stored mixture. The estimator stays unbiased: the pdf
// divided by is the one sampled from, and the mixture is MIS-weighted against the BSDF
// continuation of the actual (jittered) hit, which covers its lobe; a jitter that moves the hit
// only changes how well the proposal fits. The CPU twin (CpuPathTracer::cameraNeeSampler) builds
// the same mixture from the same centre hit.
//
// Rule at a path's camera vertex whose material's policy forms a product (mode Product or
// BsdfLobe): the pixel's entry when its centre hit the SAME material, else `mis`'s technique (the
// env alone: silhouettes, where the centre hit another object or nothing).
//
// Buffer (uint words): [0, pixels) the word offset of each pixel's entry (kNoCacheEntry: none,
// its centre hit no such material on the CPU's trace), padded to an even count, then the entries:
// a header of WAVELIT_PRODUCT_CACHE_HEADER_WORDS words (material, shares, window, normal, wo) and,
// for a per-hit product, a pad word and its pyramid's pyramidOffset(m + 1)
// masses.
#ifndef WAVELIT_PRODUCT_CACHE_GLSL
#define WAVELIT_PRODUCT_CACHE_GLSL

const uint kNoCacheEntry = 0xFFFFFFFFu;

bool pcCacheableMode(uint mode) { return mode == kModeProduct || mode == kModeBsdfLobe; }

// An entry is read and written through the buffer's u64 view, productCache64 (two words a load
// on lavapipe; render/gpu/product_cache.h keeps every entry on an 8-byte boundary). Its header,
// as u64 pairs (low word first), h = at / 2:
//   h + 0 (material, massOffset)   h + 1 (cProduct, cBsdf)   h + 2 (cEnv, k)   h + 3 (ox, oy)
//   h + 4 (m, refineLevels)        h + 5 (n.x, n.y)          h + 6 (n.z, wo.x) h + 7 (wo.y, wo.z)
// The frame is stored as its normal: the tangents are frameFromNormal's of it, as pcBuild made
// them (8 loads a camera vertex instead of 22 word loads). A per-hit pyramid starts at the odd
// word at + WAVELIT_PRODUCT_CACHE_PYRAMID_AT, after one pad word, so its sibling cells pair up
// in u64s (dsChildProbabilities).
uint64_t pcPair(uint a, uint b) { return packUint2x32(uvec2(a, b)); }
uint64_t pcPair(float a, float b) { return packUint2x32(floatBitsToUint(vec2(a, b))); }
uint64_t pcPair(float a, uint b) { return packUint2x32(uvec2(floatBitsToUint(a), b)); }

// Builds the entry at `at` from the pixel centre's camera hit: the same surface, frame and
// dsSetup as the path loop's camera vertex.
void pcBuild(uint at, vec3 origin, vec3 dir, SamplerGlobals g, uint triangleCount,
             uint materialCount) {
    uint h = at >> 1u;
    productCache64[h] = pcPair(kNoCacheEntry, 0u);
    uint tri;
    float t, b1, b2;
    if (!bvhTrace(origin, dir, 0.0, kFloatMax, false, triangleCount, tri, t, b1, b2)) return;
    BvhTriangle T = loadTriangle(tri);
    vec3 ng = normalize(cross(T.v1.xyz - T.v0.xyz, T.v2.xyz - T.v0.xyz));
    if (dot(ng, dir) > 0.0) ng = -ng;
    float b0 = 1.0 - b1 - b2;
    vec3 ns = b0 * T.n0.xyz + b1 * T.n1.xyz + b2 * T.n2.xyz;
    float len = length(ns);
    ns = len > 0.0 ? ns / len : ng;
    if (dot(ns, ng) < 0.0) ns = -ns;
    if (dot(-dir, ns) <= 0.0) ns = ng;
    uint m = min(uint(max(T.v0.w, 0.0)), materialCount - 1u);
    SamplerMaterial sm = samplerMaterials[m];
    if (!pcCacheableMode(sm.mode)) return;
    Material mat = loadMaterial(m);
    Frame frame = frameFromNormal(ns);
    vec3 wo = frameToLocal(frame, -dir);
    DirSampler s = dsSetup(g, sm, frame, wo, uint(mat.emissionType.a), mat.baseColorRoughness.rgb,
                           mat.baseColorRoughness.a);
    int massOffset = s.massOffset;
    if (massOffset < 0 && s.cProduct > 0.0) {
        // The private pyramid follows the header; its entry reads it there (dsMass). Cell 0
        // shares a u64 with the pad word, then cells (2i - 1, 2i) one u64 each (the count is odd).
        uint pyramid = at + uint(WAVELIT_PRODUCT_CACHE_PYRAMID_AT);
        uint p = pyramid >> 1u;
        productCache64[p] = pcPair(0u, floatBitsToUint(gMass[0]));
        for (int i = 1; i < pyramidOffset(s.m + 1); i += 2)
            productCache64[p + uint(i + 1) / 2u] = pcPair(gMass[i], gMass[i + 1]);
        massOffset = kMassInProductCache - int(pyramid);
    }
    productCache64[h] = pcPair(m, uint(massOffset));
    productCache64[h + 1u] = pcPair(s.cProduct, s.cBsdf);
    productCache64[h + 2u] = pcPair(s.cEnv, uint(s.k));
    productCache64[h + 3u] = pcPair(uint(s.ox), uint(s.oy));
    productCache64[h + 4u] = pcPair(uint(s.m), uint(s.refineLevels));
    productCache64[h + 5u] = pcPair(frame.n.x, frame.n.y);
    productCache64[h + 6u] = pcPair(frame.n.z, wo.x);
    productCache64[h + 7u] = pcPair(wo.y, wo.z);
}

// The camera vertex's NEE mixture of material m (cacheable mode) from the pixel's entry at `at`;
// false when the entry is missing or holds another material (the caller then sets up `mis`'s
// technique, the env alone).
bool pcLoad(uint at, uint m, SamplerGlobals g, uint brdfType, vec3 baseColor, float roughness,
            out DirSampler s) {
    if (at == kNoCacheEntry) return false;
    uint h = at >> 1u;
    uvec2 w = unpackUint2x32(productCache64[h]);
    if (w.x != m) return false;
    s.massOffset = int(w.y);
    w = unpackUint2x32(productCache64[h + 1u]);
    s.cProduct = uintBitsToFloat(w.x);
    s.cBsdf = uintBitsToFloat(w.y);
    w = unpackUint2x32(productCache64[h + 2u]);
    s.cEnv = uintBitsToFloat(w.x);
    s.k = int(w.y);
    s.cUniform = 0.0;
    s.cCosine = 0.0;
    w = unpackUint2x32(productCache64[h + 3u]);
    s.ox = int(w.x);
    s.oy = int(w.y);
    w = unpackUint2x32(productCache64[h + 4u]);
    s.m = int(w.x);
    s.refineLevels = int(w.y);
    vec2 nxy = uintBitsToFloat(unpackUint2x32(productCache64[h + 5u]));
    vec2 nzwox = uintBitsToFloat(unpackUint2x32(productCache64[h + 6u]));
    vec2 woyz = uintBitsToFloat(unpackUint2x32(productCache64[h + 7u]));
    s.frame = frameFromNormal(vec3(nxy, nzwox.x));
    s.wo = vec3(nzwox.y, woyz);
    s.brdfType = brdfType;
    s.baseColor = baseColor;
    s.roughness = roughness;
    s.cosSinYaw = g.cosSinYaw;
    s.exactOffset = g.tailOffset + uint((1 << WAVELIT_TAIL_LEVEL) * (1 << WAVELIT_TAIL_LEVEL));
    return true;
}

#endif
