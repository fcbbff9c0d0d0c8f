// The camera vertex's `wavelet` NEE mixture, cached per pixel across passes (issue 12,
// docs/performance.md "Wavelet pass cost, round 4"; render/gpu/product_cache.h packs the buffer).
// While an image accumulates, camera and scene are fixed, so the mixture a pixel's camera hit
// would build (its shares, product window and 2^m x 2^m pyramid: ~1024 BRDF x cos evaluations)
// is built ONCE, from the pixel centre's hit (jitter 0.5, 0.5), in the first pass after a reset,
// and every later pass draws from and evaluates the pdf of that stored mixture. The estimator
// stays unbiased: the pdf divided by is the one sampled from, and the mixture is MIS-weighted
// against the BSDF continuation of the actual (jittered) hit, which covers its lobe; a jitter
// that moves the hit only changes how well the proposal fits. The CPU twin (CpuPathTracer::
// cameraNeeSampler) builds the same mixture from the same centre hit.
//
// Rule at a path's camera vertex whose material's policy forms a product (mode Product or
// BsdfLobe): the pixel's entry when its centre hit the SAME material, else `mis`'s technique (the
// env alone: silhouettes, where the centre hit another object or nothing).
//
// Buffer (uint words): [0, pixels) the word offset of each pixel's entry (kNoCacheEntry: none,
// its centre hit no such material on the CPU's trace), then the entries: a header of
// WAVELIT_PRODUCT_CACHE_HEADER_WORDS words (material, shares, window, frame, wo) and, for a per-hit
// product (no precomputed bin), its pyramid's pyramidOffset(m + 1) masses.
#ifndef WAVELIT_PRODUCT_CACHE_GLSL
#define WAVELIT_PRODUCT_CACHE_GLSL

const uint kNoCacheEntry = 0xFFFFFFFFu;

bool pcCacheableMode(uint mode) { return mode == kModeProduct || mode == kModeBsdfLobe; }

void pcWriteVec3(uint at, vec3 v) {
    productCache[at] = floatBitsToUint(v.x);
    productCache[at + 1u] = floatBitsToUint(v.y);
    productCache[at + 2u] = floatBitsToUint(v.z);
}
vec3 pcReadVec3(uint at) {
    return vec3(uintBitsToFloat(productCache[at]), uintBitsToFloat(productCache[at + 1u]),
                uintBitsToFloat(productCache[at + 2u]));
}

// Builds the entry at `at` from the pixel centre's camera hit: the same surface, frame and
// dsSetup as the path loop's camera vertex.
void pcBuild(uint at, vec3 origin, vec3 dir, SamplerGlobals g, uint triangleCount,
             uint materialCount) {
    productCache[at] = kNoCacheEntry;
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
    uint pyramid = at + uint(WAVELIT_PRODUCT_CACHE_HEADER_WORDS);
    if (massOffset < 0 && s.cProduct > 0.0) {
        // The private pyramid follows the header; its entry reads it there (dsMass).
        for (int i = 0; i < pyramidOffset(s.m + 1); ++i)
            productCache[pyramid + uint(i)] = floatBitsToUint(gMass[i]);
        massOffset = kMassInProductCache - int(pyramid);
    }
    productCache[at] = m;
    productCache[at + 1u] = floatBitsToUint(s.cProduct);
    productCache[at + 2u] = floatBitsToUint(s.cBsdf);
    productCache[at + 3u] = floatBitsToUint(s.cEnv);
    productCache[at + 4u] = uint(s.k);
    productCache[at + 5u] = uint(s.ox);
    productCache[at + 6u] = uint(s.oy);
    productCache[at + 7u] = uint(s.m);
    productCache[at + 8u] = uint(s.refineLevels);
    productCache[at + 9u] = uint(massOffset);
    pcWriteVec3(at + 10u, frame.t);
    pcWriteVec3(at + 13u, frame.b);
    pcWriteVec3(at + 16u, frame.n);
    pcWriteVec3(at + 19u, wo);
}

// The camera vertex's NEE mixture of material m (cacheable mode) from the pixel's entry at `at`;
// false when the entry is missing or holds another material (the caller then sets up `mis`'s
// technique, the env alone).
bool pcLoad(uint at, uint m, SamplerGlobals g, uint brdfType, vec3 baseColor, float roughness,
            out DirSampler s) {
    if (at == kNoCacheEntry || productCache[at] != m) return false;
    s.cProduct = uintBitsToFloat(productCache[at + 1u]);
    s.cBsdf = uintBitsToFloat(productCache[at + 2u]);
    s.cEnv = uintBitsToFloat(productCache[at + 3u]);
    s.cUniform = 0.0;
    s.cCosine = 0.0;
    s.k = int(productCache[at + 4u]);
    s.ox = int(productCache[at + 5u]);
    s.oy = int(productCache[at + 6u]);
    s.m = int(productCache[at + 7u]);
    s.refineLevels = int(productCache[at + 8u]);
    s.massOffset = int(productCache[at + 9u]);
    s.frame.t = pcReadVec3(at + 10u);
    s.frame.b = pcReadVec3(at + 13u);
    s.frame.n = pcReadVec3(at + 16u);
    s.wo = pcReadVec3(at + 19u);
    s.brdfType = brdfType;
    s.baseColor = baseColor;
    s.roughness = roughness;
    s.cosSinYaw = g.cosSinYaw;
    s.exactOffset = g.tailOffset + uint((1 << WAVELIT_TAIL_LEVEL) * (1 << WAVELIT_TAIL_LEVEL));
    return true;
}

#endif
