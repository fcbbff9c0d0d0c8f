// The direction samplers' tables (gpu_sampler_data.h): word i of the `samplerWords` buffer, and
// its 64-bit pair j (words 2j, 2j + 1: doubles and aligned word pairs in one read). The including
// shader declares the buffer as `uint samplerWords[]` and `uint64_t samplerWords64[]`, or, with
// WAVELIT_SAMPLER_TEXELS, as the texel buffers `samplerWordTexels` (R32UI) and
// `samplerPairTexels` (RG32UI): path_tracer.comp on CPU devices, where lavapipe reads a texel
// through its texture path instead of a loop over the lanes (docs/performance.md "Texel buffers").
#ifndef WAVELIT_SAMPLER_WORDS_GLSL
#define WAVELIT_SAMPLER_WORDS_GLSL

#ifdef WAVELIT_SAMPLER_TEXELS
uint samplerWord(uint i) { return texelFetch(samplerWordTexels, int(i)).x; }
uint64_t samplerPair(uint j) { return packUint2x32(texelFetch(samplerPairTexels, int(j)).xy); }
#else
uint samplerWord(uint i) { return samplerWords[i]; }
uint64_t samplerPair(uint j) { return samplerWords64[j]; }
#endif

#endif
