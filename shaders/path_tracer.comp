// Progressive path tracer, one sample per pixel per dispatch added to a float sum buffer.
// Implements docs/estimator.md exactly (RNG streams, camera, environment, surfaces, BRDFs, path
// loop with Russian roulette) so its mean image matches render/cpu_path_tracer.cpp within noise.
// Plain BSDF sampling for now; the wavelet product samplers of issue 6 plug in at the marked spot.
//
// Buffers follow the layouts of renderer/scene/bvh.h and renderer/render/gpu_scene_data.h.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

// The driver passes its workgroup shape (gpu_path_tracer.cpp) so dispatch and shader agree.
#ifndef WAVELIT_WORKGROUP_X
#define WAVELIT_WORKGROUP_X 8
#define WAVELIT_WORKGROUP_Y 8
#endif
layout(local_size_x = WAVELIT_WORKGROUP_X, local_size_y = WAVELIT_WORKGROUP_Y) in;

layout(std140, binding = 0) uniform Params {
    vec4 camPosition;  // xyz
    vec4 camForward;   // xyz; w = tan(vfov / 2)
    vec4 camRight;     // xyz; w = aspect
    vec4 camUp;        // xyz
    vec4 envScale;     // rgb = intensity * tint
    vec4 envRotation;  // x = cos yaw, y = sin yaw
    uvec4 size;        // width, height, bounces, triangle count
    uvec4 envSize;     // env width, env height (0 = constant), material count, unused
} params;

layout(push_constant) uniform Pass {
    uvec2 seed; // options.seed ^ (pass * 0x9E3779B97F4A7C15), low and high words
} pass;

struct BvhNode {
    vec3 boundsMin;
    uint leftFirst;
    vec3 boundsMax;
    uint count;
};
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

layout(std430, binding = 1) readonly buffer Nodes { BvhNode bvhNodes[]; };
layout(std430, binding = 2) readonly buffer Triangles { BvhTriangle bvhTriangles[]; };
layout(std430, binding = 3) readonly buffer Materials { Material materials[]; };
layout(std430, binding = 4) readonly buffer Environment { float envTexels[]; };
layout(std430, binding = 5) buffer Accumulation { vec4 accumulation[]; };

#include "common/rng.glsl"
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

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    uvec2 size = params.size.xy;
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    uint pixelIndex = pixel.y * size.x + pixel.x;
    uint64_t seed = (uint64_t(pass.seed.y) << 32) | uint64_t(pass.seed.x);
    Pcg32 rng = pcgSeed(seed, uint64_t(pixelIndex));
    float jx = pcgFloat(rng);
    float jy = pcgFloat(rng);

    vec3 origin = params.camPosition.xyz;
    vec3 dir = cameraDirection(params.camForward.xyz, params.camRight.xyz, params.camUp.xyz,
                               params.camForward.w, params.camRight.w, size, pixel, jx, jy);
    uint bounces = params.size.z;
    uint triangleCount = params.size.w;
    uint materialCount = params.envSize.z;
    vec3 L = vec3(0.0), beta = vec3(1.0);
    for (uint depth = 0u;; ++depth) {
        uint tri;
        float t, b1, b2;
        if (!bvhTrace(origin, dir, 0.0, kFloatMax, false, triangleCount, tri, t, b1, b2)) {
            L += beta * envRadiance(dir);
            break;
        }
        BvhTriangle T = bvhTriangles[tri];
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
        Material mat = materials[m];
        L += beta * mat.emissionType.rgb;
        if (depth == bounces) break;

        // Next-event estimation and the wavelet product samplers (issue 6) go here.

        Frame frame = frameFromNormal(ns);
        float u1 = pcgFloat(rng);
        float u2 = pcgFloat(rng);
        vec3 wiLocal, f;
        float pdf;
        if (!brdfSample(uint(mat.emissionType.a), mat.baseColorRoughness.rgb,
                        mat.baseColorRoughness.a, frameToLocal(frame, -dir), u1, u2, wiLocal, f,
                        pdf) ||
            pdf <= 0.0)
            break;
        vec3 wi = frameToWorld(frame, wiLocal);
        if (dot(wi, ng) <= 0.0) break; // below the true surface: light leak otherwise
        beta *= f * (wiLocal.z / pdf);

        if (int(depth) >= kRussianRouletteDepth) {
            float q = max(kMinContinueProbability, 1.0 - max(beta.r, max(beta.g, beta.b)));
            if (pcgFloat(rng) < q) break;
            beta /= 1.0 - q;
        }
        origin = position + ng * (kRayOffset * max(1.0, length(position)));
        dir = wi;
    }
    accumulation[pixelIndex] += vec4(L, 1.0);
}
