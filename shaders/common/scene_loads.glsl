// The scene's records read through their texel views (WAVELIT_SCENE_TEXELS_BINDING: CPU devices,
// where llvmpipe gathers texels in registers) or their 64-bit storage views (common/packed64.glsl),
// unpacked into the 32-bit structs the rest of the kernel uses. Included by path_tracer.comp after
// its buffers; the compiler drops the words a caller does not use.
#ifndef WAVELIT_SCENE_LOADS_GLSL
#define WAVELIT_SCENE_LOADS_GLSL

BvhTriangle loadTriangle(uint i) {
#ifdef WAVELIT_SCENE_TEXELS_BINDING
    return BvhTriangle(uintBitsToFloat(texelFetch(bvhTriangleTexels, int(6u * i))),
                       uintBitsToFloat(texelFetch(bvhTriangleTexels, int(6u * i + 1u))),
                       uintBitsToFloat(texelFetch(bvhTriangleTexels, int(6u * i + 2u))),
                       uintBitsToFloat(texelFetch(bvhTriangleTexels, int(6u * i + 3u))),
                       uintBitsToFloat(texelFetch(bvhTriangleTexels, int(6u * i + 4u))),
                       uintBitsToFloat(texelFetch(bvhTriangleTexels, int(6u * i + 5u))));
#else
    BvhTriangle64 w = bvhTriangles64[i];
    return BvhTriangle(words4(w.v0), words4(w.v1), words4(w.v2), words4(w.n0), words4(w.n1),
                       words4(w.n2));
#endif
}

Material loadMaterial(uint m) {
#ifdef WAVELIT_SCENE_TEXELS_BINDING
    return Material(uintBitsToFloat(texelFetch(materialTexels, int(2u * m))),
                    uintBitsToFloat(texelFetch(materialTexels, int(2u * m + 1u))));
#else
    Material64 w = materials64[m];
    return Material(words4(w.baseColorRoughness), words4(w.emissionType));
#endif
}

Light loadLight(uint k) {
#ifdef WAVELIT_SCENE_TEXELS_BINDING
    uint at = 6u * k;
    return Light(uintBitsToFloat(texelFetch(lightTexels, int(at))),
                 uintBitsToFloat(texelFetch(lightTexels, int(at + 1u))),
                 uintBitsToFloat(texelFetch(lightTexels, int(at + 2u))),
                 uintBitsToFloat(texelFetch(lightTexels, int(at + 3u))),
                 uintBitsToFloat(texelFetch(lightTexels, int(at + 4u))),
                 uintBitsToFloat(texelFetch(lightTexels, int(at + 5u))));
#else
    Light64 w = analyticLights64[k];
    return Light(words4(w.positionType), words4(w.normalRadius), words4(w.emissionArea),
                 words4(w.axisUInner), words4(w.axisVOuter), words4(w.sun));
#endif
}

#endif
