// 64-bit views of path_tracer.comp's scene buffers (byte for byte the layouts of
// renderer/scene/bvh.h and gpu_scene_data.h: std430, a u64vec2 is 16 bytes aligned to 16).
// Why: lavapipe (Mesa 22.3 gallivm) loads an SSBO one lane and one component at a time, inserting
// each word into a vector that lives on the stack: a store-forwarding stall per lane and per
// component, ~45% of a `bsdf` pass in perf. A 64-bit component carries two words, so the same
// bytes cost half the loads (docs/performance.md "Lavapipe throughput (issue 12)"). On CPU devices
// the kernel now reads most of these records through texel views instead (path_tracer.comp,
// WAVELIT_SCENE_TEXELS_BINDING): these views are a GPU's reads.
// The including shader enables GL_EXT_shader_explicit_arithmetic_types_int64.
#ifndef WAVELIT_PACKED64_GLSL
#define WAVELIT_PACKED64_GLSL

struct BvhNode64 {
    u64vec4 q; // (minX, minY), (minZ, leftFirst), (maxX, maxY), (maxZ, count): low word first
};
struct BvhTriangle64 {
    u64vec2 v0, v1, v2, n0, n1, n2;
};
struct Material64 {
    u64vec2 baseColorRoughness, emissionType;
};
struct Light64 {
    u64vec2 positionType, normalRadius, emissionArea, axisUInner, axisVOuter, sun;
};

// The two 32-bit words of a 64-bit component as floats (x the low word: little endian).
vec2 words2(uint64_t w) { return uintBitsToFloat(unpackUint2x32(w)); }
vec4 words4(u64vec2 w) { return vec4(words2(w.x), words2(w.y)); }
uint highWord(uint64_t w) { return unpackUint2x32(w).y; }
u64vec2 packWords4(vec4 v) {
    return u64vec2(packUint2x32(floatBitsToUint(v.xy)), packUint2x32(floatBitsToUint(v.zw)));
}

#endif
