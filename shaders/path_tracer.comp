// Progressive path tracer, one sample per pixel per dispatch added to a float sum buffer.
// Implements docs/estimator.md exactly (RNG streams, camera, environment, surfaces, BRDFs, path
// loop with Russian roulette) so its mean image matches render/reference/cpu_path_tracer.cpp within noise.
// Next-event estimation of the analytic lights with MIS (common/lights.glsl). When the driver
// defines WAVELIT_DIRECTION_SAMPLERS (any --sampler but bsdf), a per-vertex direction sampler of
// sampling/direction_sampler.glsl (issue 6) either draws the continuation (uniform, cosine; its pdf
// is then what the light MIS weights use) or is the technique of the next-event estimation of
// DIRECT environment light (env, mis, wavelet, oracle; issue 20), whose continuation is the BSDF
// sample, MIS-weighted against it (docs/estimator.md "Direction samplers").
//
// Buffers follow the layouts of renderer/scene/bvh.h and renderer/render/gpu/gpu_scene_data.h.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

// The driver passes its workgroup shape (gpu_path_tracer.cpp) so dispatch and shader agree.
// On lavapipe the shape barely matters: a group runs as vectors of 8 x-consecutive invocations
// whatever its size (8x8, 16x4, 32x2, 64x1, 8x4, 16x16 within noise; docs/performance.md
// "Lavapipe throughput (issue 12)").
#ifndef WAVELIT_WORKGROUP_X
#define WAVELIT_WORKGROUP_X 8
#define WAVELIT_WORKGROUP_Y 8
#endif
layout(local_size_x = WAVELIT_WORKGROUP_X, local_size_y = WAVELIT_WORKGROUP_Y) in;

layout(std140, binding = 0) readonly buffer Params { // not a uniform block: gpu_path_tracer.h
    vec4 camPosition;  // xyz
    vec4 camForward;   // xyz; w = tan(vfov / 2)
    vec4 camRight;     // xyz; w = aspect
    vec4 camUp;        // xyz
    vec4 envScale;     // rgb = intensity * tint
    vec4 envRotation;  // x = cos yaw, y = sin yaw
    uvec4 size;        // width, height, bounces, triangle count
    uvec4 envSize;     // env width, env height (0 = constant), material count, light count
    vec4 lightInfo;    // x = light selection probability 1/n (computed on the CPU, as LightSet)
    uvec4 samplerInfo; // sampler kind code, env lit (0/1), word offset of the 8^2 env averages,
                       // env map level N
    vec4 samplerEnv;   // x = the sampler env map's mean luminance, y = `mis`'s shadow-ray roulette
                       // constant c (misEnvRoulette, from the env's effective solid angle)
} params;

layout(push_constant) uniform Pass {
    uint seedKey; // util::PathSampler::seedKey(options.seed)
    uint index;   // RenderOptions::firstPass + the passes since the last reset
    uint buildCache; // 1: build the per-pixel product cache first (sampling/product_cache.glsl)
} pass;

// The scene buffers are declared through their 64-bit views (common/packed64.glsl: half the
// loads on lavapipe); these are the 32-bit records the kernel unpacks them into.
struct BvhTriangle {
    vec4 v0; // w = material index
    vec4 v1; // w = object index
    vec4 v2;
    vec4 n0;
    vec4 n1;
    vec4 n2;
};
struct Material {
    vec4 baseColorRoughness; // rgb = baseColor, a = roughness
    vec4 emissionType;       // rgb = emission, a = BRDF type code (common/brdf.glsl)
};

#include "common/packed64.glsl"
layout(std430, binding = 1) readonly buffer Nodes { BvhNode64 bvhNodes64[]; };
layout(std430, binding = 2) readonly buffer Triangles { BvhTriangle64 bvhTriangles64[]; };
layout(std430, binding = 3) readonly buffer Materials { Material64 materials64[]; };
layout(std430, binding = 4) readonly buffer Environment { float envTexels[]; };
layout(std430, binding = 5) buffer Accumulation { u64vec2 accumulation[]; }; // vec4 sums

#include "common/lights.glsl"
layout(std430, binding = 6) readonly buffer Lights { Light64 analyticLights64[]; };
#include "common/scene_loads.glsl"

#ifdef WAVELIT_DIRECTION_SAMPLERS
#include "sampling/sampler_structs.glsl"
layout(std430, binding = 7) readonly buffer EnvTable { EnvNode envNodes[]; };
layout(std430, binding = 7) readonly buffer EnvTable64 { u64vec2 envNodes64[]; }; // the same nodes
layout(std430, binding = 8) readonly buffer SamplerMaterials { SamplerMaterial samplerMaterials[]; };
layout(std430, binding = 9) readonly buffer SamplerWords { uint samplerWords[]; };
// The same buffer as 64-bit words: doubles and aligned word pairs in one load (env_exact.glsl).
layout(std430, binding = 9) readonly buffer SamplerWords64 { uint64_t samplerWords64[]; };
#ifdef WAVELIT_PRODUCT_CACHE_BINDING
// `wavelet` with a product: the camera vertex's mixture per pixel (sampling/product_cache.glsl).
layout(std430, binding = WAVELIT_PRODUCT_CACHE_BINDING) buffer ProductCache { uint productCache[]; };
// The same buffer as 64-bit words: the entries are read and written through this view alone (two
// words a load; product_cache.glsl), the 32-bit one only reads the pixels' offsets.
layout(std430, binding = WAVELIT_PRODUCT_CACHE_BINDING) buffer ProductCache64 { uint64_t productCache64[]; };
#endif
#include "sampling/direction_sampler.glsl"
#endif

#ifdef WAVELIT_LIGHT_GROUPS
#include "common/light_groups.glsl"
#endif

#include "common/path_sampler.glsl"
#include "common/camera.glsl"
#include "common/environment.glsl"
#include "common/bvh.glsl"
#include "common/brdf.glsl"

const float kRayOffset = 1e-4;             // x max(1, |hit|): scale-aware self-intersection epsilon
const float kMinContinueProbability = 0.05; // Russian roulette floor
const int kRussianRouletteDepth = 2;

vec3 envRadiance(vec3 dir) {
    return environmentRadiance(dir, params.envScale.rgb, params.envRotation.xy, params.envSize.xy);
}

// LightSet::emissionAlongRay with the Mis strategy: every light crossed before the surface hit
// (tMax) or, when the ray escaped, also the sun; weight 1 for camera rays.
// With light groups, each light's term (times the path throughput beta) also goes to its layer.
vec3 emissionAlongRay(vec3 origin, vec3 dir, float tMax, bool escaped, float bsdfPdf,
                      bool cameraRay, uint lightCount, float selection, vec3 beta,
                      uint pixelIndex) {
    vec3 sum = vec3(0.0);
    for (uint k = 0u; k < lightCount; ++k) {
        Light l = loadLight(k);
        float t;
        if (!lightEvalHit(l, origin, dir, tMax, escaped, t)) continue;
        float w = 1.0;
        if (!cameraRay) w = powerHeuristic(bsdfPdf, selection * lightPdf(l, origin, dir));
        sum += w * l.emissionArea.rgb;
#ifdef WAVELIT_LIGHT_GROUPS
        splatGroup(groupOfLight[k], pixelIndex, beta * (w * l.emissionArea.rgb));
#endif
    }
    return sum;
}

// CpuPathTracer::nextEvent with the Mis strategy, from the continuation-ray origin o.
vec3 nextEvent(uint type, vec3 baseColor, float roughness, Frame frame, vec3 wo, vec3 ng, vec3 o,
               float uSelect, float u1, float u2, uint lightCount, float selection,
               uint triangleCount
#ifdef WAVELIT_DIRECTION_SAMPLERS
               , DirSampler ds, bool dsDrawsContinuation
#endif
) {
    Light l = loadLight(min(uint(uSelect * float(lightCount)), lightCount - 1u));
    LightSample ls = lightSample(l, o, u1, u2);
    if (!ls.valid || !(ls.pdf > 0.0)) return vec3(0.0);
    if (dot(ls.wi, ng) <= 0.0) return vec3(0.0);
    vec3 wi = frameToLocal(frame, ls.wi);
    if (wi.z <= 0.0) return vec3(0.0);
    vec3 f = brdfEval(type, baseColor, roughness, wo, wi);
    if (all(equal(f, vec3(0.0)))) return vec3(0.0);
    uint tri;
    float t, b1, b2;
    if (bvhTrace(o, ls.wi, 0.0, ls.distance, true, triangleCount, tri, t, b1, b2))
        return vec3(0.0);
    // The pdf of the continuation's technique at wi (the vertex sampler's only when it draws it).
    float bsdfPdf = ls.delta ? 0.0 : brdfPdf(type, roughness, wo, wi);
#ifdef WAVELIT_DIRECTION_SAMPLERS
    if (!ls.delta && dsDrawsContinuation) bsdfPdf = dsPdf(ds, ls.wi);
#endif
    float w = ls.delta ? 1.0 : powerHeuristic(selection * ls.pdf, bsdfPdf);
    return f * ls.value * (wi.z * w / (ls.pdf * selection));
}

#ifdef WAVELIT_DIRECTION_SAMPLERS
#include "sampling/env_nee.glsl"
#endif
#ifdef WAVELIT_PRODUCT_CACHE_BINDING
#include "sampling/product_cache.glsl"
#endif

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    uvec2 size = params.size.xy;
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    uint pixelIndex = pixel.y * size.x + pixel.x;
    PathSampler rng = psStart(pass.seedKey, pixelIndex, pass.index);
    vec2 jitter = psNext2D(rng);
    float jx = jitter.x, jy = jitter.y;

    vec3 origin = params.camPosition.xyz;
    vec3 dir = cameraDirection(params.camForward.xyz, params.camRight.xyz, params.camUp.xyz,
                               params.camForward.w, params.camRight.w, size, pixel, jx, jy);
    uint bounces = params.size.z;
    uint triangleCount = params.size.w;
    uint materialCount = params.envSize.z;
    uint lightCount = params.envSize.w;
    float selection = params.lightInfo.x;
    vec3 L = vec3(0.0), beta = vec3(1.0);
    float scatterPdfOfDir = 0.0; // solid-angle pdf with which the last vertex drew `dir`
#ifdef WAVELIT_DIRECTION_SAMPLERS
    // The tracer's sampler is fixed when its pipeline is made (gpu_path_tracer.cpp defines it):
    // a constant lets the compiler drop the other kinds' code (uniform/cosine continuations, the
    // general mixture set-up and pdfs); params.samplerInfo.x carries the same code.
    // docs/performance.md "`mis` pass cost, round 3": -0.65 of a 10.6 CPU-s `mis` pass.
    const uint kind = WAVELIT_SAMPLER_KIND;
    bool lit = params.samplerInfo.y != 0u;
    // The kinds whose vertex sampler draws the continuation (else it is the env NEE technique).
    bool continuationFromSampler = kind == kSamplerUniform || kind == kSamplerCosine;
    bool envNee = kind == kSamplerEnv || kind == kSamplerMis || kind == kSamplerWavelet ||
                  kind == kSamplerOracle;
    // The vertex that drew `dir` estimated direct env light by NEE with `ds` (still its sampler:
    // set up per vertex, and an escaping ray sets up none).
#ifdef WAVELIT_PRODUCT_CACHE_BINDING
    // The pixel's cached camera-vertex mixture, built in the first pass after a reset.
    uint cacheAt = productCache[pixelIndex];
    if (pass.buildCache != 0u && cacheAt != kNoCacheEntry && lit) {
        SamplerGlobals cg;
        cg.kind = kind;
        cg.lit = true;
        cg.tailOffset = params.samplerInfo.z;
        cg.envLevel = int(params.samplerInfo.w);
        cg.envMean = params.samplerEnv.x;
        cg.cosSinYaw = params.envRotation.xy;
        pcBuild(cacheAt, origin,
                cameraDirection(params.camForward.xyz, params.camRight.xyz, params.camUp.xyz,
                                params.camForward.w, params.camRight.w, size, pixel, 0.5, 0.5),
                cg, triangleCount, materialCount);
    }
#endif
    bool neeOfDir = false;
    // ...and that technique was the env alone with `mis`'s weights (mis; wavelet past its product
    // vertices or under the EnvMis policy): its pdf and radiance come from one texel lookup.
    bool misNeeOfDir = false;
    DirSampler ds;
#endif
    for (uint depth = 0u;; ++depth) {
        uint tri;
        float t, b1, b2;
        bool found = bvhTrace(origin, dir, 0.0, kFloatMax, false, triangleCount, tri, t, b1, b2);
        // Analytic lights crossed before the surface (or the sun, when the ray escapes).
        if (lightCount > 0u)
            L += beta * emissionAlongRay(origin, dir, t, !found, scatterPdfOfDir, depth == 0u,
                                         lightCount, selection, beta, pixelIndex);
        if (!found) {
            float w = 1.0;
#ifdef WAVELIT_DIRECTION_SAMPLERS
            // mis: one texel lookup gives both the radiance and the env technique's pdf.
            if (neeOfDir && misNeeOfDir) {
                uvec2 exactSize = envExactSize(ds.exactOffset);
                uvec2 t = equirectTexelOf(dir, ds.cosSinYaw, exactSize);
                w = powerHeuristic(scatterPdfOfDir,
                                   float(envExactTexelPdfSized(ds.exactOffset, exactSize, t)));
                vec3 escaped = beta * (w * envTexelRadiance(t));
                L += escaped;
#ifdef WAVELIT_LIGHT_GROUPS
                splatGroup(environmentGroup, pixelIndex, escaped);
#endif
                break;
            }
            if (neeOfDir)
                w = kind == kSamplerEnv ? 0.0 : powerHeuristic(scatterPdfOfDir, dsPdf(ds, dir));
#endif
            vec3 escaped = beta * (w * envRadiance(dir));
            L += escaped;
#ifdef WAVELIT_LIGHT_GROUPS
            splatGroup(environmentGroup, pixelIndex, escaped);
#endif
            break;
        }
        BvhTriangle T = loadTriangle(tri);
        vec3 position = origin + t * dir;
        vec3 ng = normalize(cross(T.v1.xyz - T.v0.xyz, T.v2.xyz - T.v0.xyz));
        if (dot(ng, dir) > 0.0) ng = -ng;
        float b0 = 1.0 - b1 - b2;
        vec3 ns = b0 * T.n0.xyz + b1 * T.n1.xyz + b2 * T.n2.xyz;
        float len = length(ns);
        ns = len > 0.0 ? ns / len : ng;
        if (dot(ns, ng) < 0.0) ns = -ns;
        if (dot(-dir, ns) <= 0.0) ns = ng;

        uint m = min(uint(max(T.v0.w, 0.0)), materialCount - 1u);
        Material mat = loadMaterial(m);
        L += beta * mat.emissionType.rgb;
#ifdef WAVELIT_LIGHT_GROUPS
        if (any(notEqual(mat.emissionType.rgb, vec3(0.0))))
            splatGroup(emissionGroup, pixelIndex, beta * mat.emissionType.rgb);
#endif
        if (depth == bounces) break;

        Frame frame = frameFromNormal(ns);
        uint brdfType = uint(mat.emissionType.a);
        vec3 wo = frameToLocal(frame, -dir);
        // Lights are sampled from the continuation-ray origin, as the CPU tracer does.
        vec3 next = position + ng * (kRayOffset * max(1.0, length(position)));
#ifdef WAVELIT_DIRECTION_SAMPLERS
        SamplerGlobals globals;
        // mis's NEE: the env alone; wavelet's too past its product vertices (vertexSamplerKind).
        bool envTechniqueHere =
            kind == kSamplerMis ||
            (kind == kSamplerWavelet && depth >= uint(WAVELIT_WAVELET_PRODUCT_VERTICES));
        globals.kind = envTechniqueHere ? kSamplerEnv : kind;
        globals.lit = params.samplerInfo.y != 0u;
        globals.tailOffset = params.samplerInfo.z;
        globals.envLevel = int(params.samplerInfo.w);
        globals.envMean = params.samplerEnv.x;
        globals.cosSinYaw = params.envRotation.xy;
        bool vertexNee = envNee && lit;
#ifdef WAVELIT_PRODUCT_CACHE_BINDING
        // wavelet: the camera vertex of a product material draws from the pixel's cached
        // mixture (its centre hit the same material), every other vertex (and a camera vertex
        // the cache does not hold) uses `mis`'s technique — bsdf alone for a material without
        // tables, as dsSetup would; the product code lives in pcBuild alone.
        if (vertexNee) {
            SamplerMaterial sm = samplerMaterials[m];
            if (!(depth == 0u && pcCacheableMode(sm.mode) &&
                  pcLoad(cacheAt, m, globals, brdfType, mat.baseColorRoughness.rgb,
                         mat.baseColorRoughness.a, ds))) {
                globals.kind = depth == 0u && sm.mode == kModeBsdfOnly ? kSamplerBsdf : kSamplerEnv;
                ds = dsSetupWith(false, globals, sm, frame, wo, brdfType,
                                 mat.baseColorRoughness.rgb, mat.baseColorRoughness.a);
            }
        }
#else
        if (continuationFromSampler || vertexNee)
            ds = dsSetup(globals, samplerMaterials[m], frame, wo, brdfType,
                         mat.baseColorRoughness.rgb, mat.baseColorRoughness.a);
#endif
#endif
        if (lightCount > 0u) {
            float uSelect = psNext1D(rng);
            vec2 ul = psNext2D(rng);
            vec3 direct = beta * nextEvent(brdfType, mat.baseColorRoughness.rgb,
                                           mat.baseColorRoughness.a, frame, wo, ng, next, uSelect,
                                           ul.x, ul.y, lightCount, selection, triangleCount
#ifdef WAVELIT_DIRECTION_SAMPLERS
                                           , ds, continuationFromSampler
#endif
            );
            L += direct;
#ifdef WAVELIT_LIGHT_GROUPS
            splatGroup(groupOfLight[min(uint(uSelect * float(lightCount)), lightCount - 1u)],
                       pixelIndex, direct);
#endif
        }
#ifdef WAVELIT_DIRECTION_SAMPLERS
        if (envNee) {
            vec2 ue = psNext2D(rng);
            float ue3 = psNext1D(rng);
            if (vertexNee) {
                // The env technique alone (mis, wavelet's env-only vertices, env): one texel
                // lookup; `mis`'s roulette wherever the NEE is mis's (not for `env`).
                bool techniqueOnly = ds.cEnv == 1.0;
                bool roulette = techniqueOnly && kind != kSamplerEnv;
                vec3 envDirect = beta * envNextEvent(ds, techniqueOnly, roulette, beta, brdfType,
                                                     mat.baseColorRoughness.rgb,
                                                     mat.baseColorRoughness.a, frame, wo, ng, next,
                                                     ue.x, ue.y, ue3, kind == kSamplerEnv,
                                                     triangleCount);
                L += envDirect;
#ifdef WAVELIT_LIGHT_GROUPS
                splatGroup(environmentGroup, pixelIndex, envDirect);
#endif
            }
        }
#endif

        vec2 u12 = psNext2D(rng);
        float u1 = u12.x, u2 = u12.y;
        vec3 wiLocal, f;
        float pdf;
        vec3 wi;
#ifdef WAVELIT_DIRECTION_SAMPLERS
        if (continuationFromSampler) {
            // The mixture's draw; the estimator divides by its pdf (architecture.md §4).
            float u3 = psNext1D(rng);
            vec3 wiWorld;
            if (!dsSample(ds, u1, u2, u3, wiWorld, pdf)) break;
            wiLocal = frameToLocal(frame, wiWorld);
            if (wiLocal.z <= 0.0) break;
            f = brdfEval(brdfType, mat.baseColorRoughness.rgb, mat.baseColorRoughness.a, wo,
                         wiLocal);
            wi = wiWorld;
        } else
#endif
        {
            if (!brdfSample(brdfType, mat.baseColorRoughness.rgb, mat.baseColorRoughness.a, wo,
                            u1, u2, wiLocal, f, pdf) ||
                pdf <= 0.0)
                break;
            wi = frameToWorld(frame, wiLocal);
        }
        if (dot(wi, ng) <= 0.0) break; // below the true surface: light leak otherwise
        beta *= f * (wiLocal.z / pdf);
        scatterPdfOfDir = pdf;
#ifdef WAVELIT_DIRECTION_SAMPLERS
        neeOfDir = vertexNee;
        misNeeOfDir = kind != kSamplerEnv && ds.cEnv == 1.0;
#endif

        if (int(depth) >= kRussianRouletteDepth) {
            float q = max(kMinContinueProbability, 1.0 - max(beta.r, max(beta.g, beta.b)));
            if (psNext1D(rng) < q) break;
            beta /= 1.0 - q;
        }
        origin = next;
        dir = wi;
    }
    accumulation[pixelIndex] = packWords4(words4(accumulation[pixelIndex]) + vec4(L, 1.0));
}
