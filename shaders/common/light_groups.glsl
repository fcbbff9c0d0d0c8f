// LightMix layers (docs/lightmix.md, docs/estimator.md "Light groups"): with WAVELIT_LIGHT_GROUPS
// every radiance term the path tracer adds to a pixel is also added to the layer of its emitter's
// group. The driver (gpu_path_tracer.cpp) passes the two binding numbers; the info buffer is
// packed by packGpuLightGroups (render/gpu/gpu_light_groups.h): group count, environment group,
// emission group (kNoGroup: none), pixel count, then one group per analytic light.
// Layers are float RGB, group-major: group g's pixel p at 3 (g · pixels + p). Each invocation
// owns its pixel, so plain adds need no atomics.
layout(std430, binding = WAVELIT_GROUP_INFO_BINDING) readonly buffer LightGroupInfo {
    uint groupCount;
    uint environmentGroup;
    uint emissionGroup;
    uint groupPixels;
    uint groupOfLight[];
};
layout(std430, binding = WAVELIT_GROUP_LAYERS_BINDING) buffer LightGroupLayers {
    float groupLayers[];
};

const uint kNoGroup = 0xFFFFFFFFu;

void splatGroup(uint group, uint pixelIndex, vec3 radiance) {
    if (group == kNoGroup) return;
    uint base = 3u * (group * groupPixels + pixelIndex);
    groupLayers[base + 0u] += radiance.r;
    groupLayers[base + 1u] += radiance.g;
    groupLayers[base + 2u] += radiance.b;
}
