// The direction samplers' buffer element types, std430 twins of the C++ layouts
// (render/gpu/gpu_sampler_data.h: wavelet::HierarchicalSampler::TableNode, GpuSamplerMaterial).
// Shaders include this, declare their buffers of these types at their own bindings, then include
// common/direction_sampler.glsl.
#ifndef WAVELIT_SAMPLER_STRUCTS_GLSL
#define WAVELIT_SAMPLER_STRUCTS_GLSL

struct EnvNode {
    float py0, px0y0, px0y1;
    int firstChild;
};

struct SamplerMaterial {
    uint mode, tableOffset, nodeOffset, scalingOffset;
    float mixBsdf, capHalfAngle;
    uint aroundNormal, refineMaxLevels;
    float refineCellAngle;
    uint pad0, pad1, pad2;
};

#endif
