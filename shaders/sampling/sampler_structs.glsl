// The direction samplers' types: the buffer elements, std430 twins of the C++ layouts
// (render/gpu/gpu_sampler_data.h: wavelet::HierarchicalSampler::TableNode, GpuSamplerMaterial), and
// one hit's sampler (DirSampler) with the tracer-wide inputs (SamplerGlobals).
// Shaders include this, declare their buffers of these types at their own bindings, then include
// sampling/direction_sampler.glsl. Every constant the samplers share with the C++ ones is a
// WAVELIT_* #define from render/gpu/sampler_shader_defines.h, appended at pipeline creation.
#ifndef WAVELIT_SAMPLER_STRUCTS_GLSL
#define WAVELIT_SAMPLER_STRUCTS_GLSL

#ifndef WAVELIT_FLAT_NODE_WORDS
#error "the sampler shaders need samplerShaderDefines() (render/gpu/sampler_shader_defines.h)"
#endif

#include "common/sampling.glsl"

struct EnvNode {
    float py0, px0y0, px0y1;
    int firstChild;
};

struct SamplerMaterial {
    uint mode, tableOffset, nodeOffset, scalingOffset;
    float mixBsdf, capHalfAngle;
    uint aroundNormal, refineMaxLevels;
    float refineCellAngle;
};

// One shading point's mixture (DirectionSampler's state).
struct DirSampler {
    float cProduct, cBsdf, cEnv, cUniform, cCosine; // mixture weights (sum 1)
    int k, ox, oy, m;                               // product window and level
    int refineLevels;                               // lobe refinement levels below the leaves
    int massOffset; // -1: the private pyramid; <= -2: the pixel's cached one (product_cache.glsl)
    Frame frame;
    vec3 wo; // shading-local
    uint brdfType;
    vec3 baseColor;
    float roughness;
    vec2 cosSinYaw;
    uint exactOffset; // word offset of the exact env tables (sampling/env_exact.glsl)
};

struct SamplerGlobals {
    uint kind;       // kSampler*
    bool lit;        // the env has light (else env techniques are absent)
    uint tailOffset; // word offset of the env's 2^WAVELIT_TAIL_LEVEL square cell averages
    int envLevel;    // the env map's level N (2^N x 2^N texels)
    float envMean;   // the env map's mean luminance (its level-0 average)
    vec2 cosSinYaw;
};

// Luminance of BRDF x cos at world direction wi (0 below the surface): DirectionSampler::brdfCos.
// Defined in sampling/direction_sampler.glsl; the product samplers weight by it.
float dsBrdfCos(DirSampler s, vec3 wiWorld);

#endif
