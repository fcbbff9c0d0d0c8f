// Reading one material's flat product tables (render/sampling/product/env_product_tables.h,
// MaterialProductTables::flatten(); the word layout is flat_product_layout.h's, handed over as the
// WAVELIT_FLAT_* defines). The including shader declares
//     buffer ... { uint samplerWords[]; };  buffer ... { uint64_t samplerWords64[]; };
// (the same buffer) holding each material's header at SamplerMaterial.tableOffset (odd), its node
// words at nodeOffset (even) and its scaling floats at scalingOffset; word pairs are read through
// the u64 view (gpu_sampler_data.cpp puts them on 8-byte boundaries).
#ifndef WAVELIT_ENV_PRODUCT_TABLES_GLSL
#define WAVELIT_ENV_PRODUCT_TABLES_GLSL

#include "common/octahedral.glsl"
#include "sampling/sampler_words.glsl"

uint flatHeader(SamplerMaterial sm, uint field) { return samplerWord(sm.tableOffset + field); }

// The bin of env-local axis direction `axisLocal` (MaterialProductTables::binOf): its window
// (k, ox, oy) and env factor.
void flatBinOf(SamplerMaterial sm, vec3 axisLocal, out int k, out int ox, out int oy,
               out uint factor) {
    int bins = 1 << int(flatHeader(sm, WAVELIT_FLAT_BIN_LEVEL));
    vec2 p = octToSquare(axisLocal);
    int bx = min(int(p.x * float(bins)), bins - 1), by = min(int(p.y * float(bins)), bins - 1);
    uint at = sm.tableOffset + WAVELIT_FLAT_HEADER_WORDS + WAVELIT_FLAT_BIN_WORDS * uint(by * bins + bx);
    // (k, ox) and (oy, factor): two u64 loads from the even `at`.
    uvec2 kox = unpackUint2x32(samplerPair((at + WAVELIT_FLAT_BIN_K) >> 1u));
    uvec2 oyf = unpackUint2x32(samplerPair((at + WAVELIT_FLAT_BIN_OY) >> 1u));
    k = int(kox.x);
    ox = int(kox.y);
    oy = int(oyf.x);
    factor = oyf.y;
}

// Where factor `factor`'s node words start (its first node's word index) and how many nodes.
void flatFactorNodes(SamplerMaterial sm, uint factor, out uint firstNode, out uint nodeCount) {
    uint at = sm.tableOffset + WAVELIT_FLAT_HEADER_WORDS +
              WAVELIT_FLAT_BIN_WORDS * flatHeader(sm, WAVELIT_FLAT_BIN_COUNT) +
              WAVELIT_FLAT_FACTOR_WORDS * factor;
    uvec2 w = unpackUint2x32(samplerPair((at + WAVELIT_FLAT_FACTOR_FIRST_NODE) >> 1u));
    firstNode = w.x;
    nodeCount = w.y;
}

// The factor's root scaling coefficient F0(0,0).
float flatScaling(SamplerMaterial sm, uint factor) {
    return uintBitsToFloat(samplerWord(sm.scalingOffset + factor));
}

// Node `node` (relative to the factor's first) of a factor: its three Haar details and the
// indices of its four children (-1: none). Nodes start at even words with an even stride, the
// first detail at an odd word: the details in two loads (the first alone, then a u64), the
// children in two u64s, not seven word loads.
uint flatNodeBase(SamplerMaterial sm, uint firstNode, int node) {
    return sm.nodeOffset + (firstNode + uint(node)) * WAVELIT_FLAT_NODE_WORDS;
}
vec3 flatNodeDetails(uint base) {
    return vec3(uintBitsToFloat(samplerWord(base + WAVELIT_FLAT_NODE_DETAIL)),
                uintBitsToFloat(unpackUint2x32(samplerPair((base + WAVELIT_FLAT_NODE_DETAIL + 1u) >> 1u))));
}
ivec4 flatNodeChildren(uint base) {
    uint at = (base + WAVELIT_FLAT_NODE_CHILD) >> 1u;
    return ivec4(unpackUint2x32(samplerPair(at)), unpackUint2x32(samplerPair(at + 1u)));
}

#endif
