// Progressive path tracer, one sample per pixel per dispatch added to a float sum buffer.
// Implements docs/estimator.md exactly (RNG streams, camera, environment, surfaces, BRDFs, path
// loop with Russian roulette) so its mean image matches render/reference/cpu_path_tracer.cpp within noise.
// The loop's two steps, a ray traced and a scattering vertex shaded, are path_vertex.glsl's
// traceSegment and shadeVertex (which says why main() has two code shapes). Compiled with
// WAVELIT_BUILD_PRODUCT_CACHE, the file is instead the kernel that builds `wavelet`'s per-pixel
// camera-vertex product cache (the first main() below).
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
// The same buffers as texels (the driver's choice on CPU devices, gpu_path_tracer.cpp; the
// order is gpu_path_tracer_impl.h's TexelView): lavapipe reads a texel through its texture path,
// a gather in registers, where an SSBO read is a loop over the lanes with a bounds check and a
// stack round trip each (docs/performance.md "Texel buffers").
#ifdef WAVELIT_SCENE_TEXELS_BINDING
layout(binding = WAVELIT_SCENE_TEXELS_BINDING) uniform usamplerBuffer bvhNodeTexels;
layout(binding = WAVELIT_SCENE_TEXELS_BINDING + 1) uniform usamplerBuffer bvhTriangleTexels;
layout(binding = WAVELIT_SCENE_TEXELS_BINDING + 2) uniform usamplerBuffer materialTexels;
layout(binding = WAVELIT_SCENE_TEXELS_BINDING + 3) uniform usamplerBuffer lightTexels;
layout(binding = WAVELIT_SCENE_TEXELS_BINDING + 4) uniform samplerBuffer envTexelView;
#endif
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
#ifdef WAVELIT_SCENE_TEXELS_BINDING
#define WAVELIT_SAMPLER_TEXELS 1 // sampling/sampler_words.glsl
layout(binding = WAVELIT_SCENE_TEXELS_BINDING + 5) uniform usamplerBuffer samplerWordTexels;
layout(binding = WAVELIT_SCENE_TEXELS_BINDING + 6) uniform usamplerBuffer samplerPairTexels;
#endif
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

vec3 envRadiance(vec3 dir) {
    return environmentRadiance(dir, params.envScale.rgb, params.envRotation.xy, params.envSize.xy);
}

#ifdef WAVELIT_DIRECTION_SAMPLERS
// What a vertex sampler reads of the params block (sampler_structs.glsl), for technique `kind`
// with the env lit or not: a path vertex's and the product cache's build alike.
SamplerGlobals samplerGlobals(uint kind, bool lit) {
    SamplerGlobals g;
    g.kind = kind;
    g.lit = lit;
    g.tailOffset = params.samplerInfo.z;
    g.envLevel = int(params.samplerInfo.w);
    g.envMean = params.samplerEnv.x;
    g.cosSinYaw = params.envRotation.xy;
    return g;
}
#endif

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

#include "path_vertex.glsl"

#ifdef WAVELIT_BUILD_PRODUCT_CACHE
// The product cache's own kernel (gpu_path_tracer_pass.cpp dispatches it over each piece of the
// first pass after a reset, before the tracing kernel): each pixel's camera-vertex mixture, built
// from the pixel centre's hit. Its code lives in a pipeline of its own because carried in the
// tracing kernel as a branch taken once per reset, it cost every lavapipe pass ~10%
// (docs/performance.md "Wavelet pass cost, round 6").
void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    uvec2 size = params.size.xy;
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    uint at = productCache[pixel.y * size.x + pixel.x];
    if (at == kNoCacheEntry || params.samplerInfo.y == 0u) return;
    pcBuild(at, params.camPosition.xyz,
            cameraDirection(params.camForward.xyz, params.camRight.xyz, params.camUp.xyz,
                            params.camForward.w, params.camRight.w, size, pixel, 0.5, 0.5),
            samplerGlobals(WAVELIT_SAMPLER_KIND, true), params.size.w, params.envSize.z);
}
#else
void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    uvec2 size = params.size.xy;
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    PathState st;
    st.pixelIndex = pixel.y * size.x + pixel.x;
    st.rng = psStart(pass.seedKey, st.pixelIndex, pass.index);
    vec2 jitter = psNext2D(st.rng);
    st.origin = params.camPosition.xyz;
    st.dir = cameraDirection(params.camForward.xyz, params.camRight.xyz, params.camUp.xyz,
                             params.camForward.w, params.camRight.w, size, pixel, jitter.x,
                             jitter.y);
    st.depth = 0u;
    st.L = vec3(0.0);
    st.beta = vec3(1.0);
#ifdef WAVELIT_PRODUCT_CACHE_BINDING
    // The pixel's cached camera-vertex mixture (built by the cache kernel above).
    st.cacheAt = productCache[st.pixelIndex];
#endif
    st.scatterPdf = 0.0;
    st.neeOfDir = false;
    st.misNeeOfDir = false;
#ifdef WAVELIT_DIRECTION_SAMPLERS
    const bool wavelet = WAVELIT_SAMPLER_KIND == kSamplerWavelet;
#else
    const bool wavelet = false;
#endif
#ifdef WAVELIT_SPLIT_CAMERA_VERTEX
    if (wavelet) {
        // `wavelet`'s camera vertex and its continuation in their own copies (path_vertex.glsl).
        if (traceSegment(false, st) && shadeVertex(true, st) && traceSegment(true, st))
            while (shadeVertex(false, st) && traceSegment(false, st)) {}
    } else
#endif
    {
        for (;;) {
            if (!traceSegment(wavelet && st.depth == 1u, st)) break;
            if (!shadeVertex(wavelet && st.depth == 0u, st)) break;
        }
    }
    accumulation[st.pixelIndex] =
        packWords4(words4(accumulation[st.pixelIndex]) + vec4(st.L, 1.0));
}
#endif
