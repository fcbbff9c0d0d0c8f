// Reading one material's flat product tables (render/sampling/product/env_product_tables.h,
// MaterialProductTables::flatten(); the word layout is flat_product_layout.h's, handed over as the
// WAVELIT_FLAT_* defines). The including shader declares
//     buffer ... { uint samplerWords[]; };
// holding each material's header at SamplerMaterial.tableOffset, its node words at nodeOffset and
// its scaling floats at scalingOffset.
#ifndef WAVELIT_ENV_PRODUCT_TABLES_GLSL
#define WAVELIT_ENV_PRODUCT_TABLES_GLSL

#include "common/octahedral.glsl"

uint flatHeader(SamplerMaterial sm, uint field) { return samplerWords[sm.tableOffset + field]; }

// The bin of env-local axis direction `axisLocal` (MaterialProductTables::binOf): its window
// (k, ox, oy) and env factor.
void flatBinOf(SamplerMaterial sm, vec3 axisLocal, out int k, out int ox, out int oy,
               out uint factor) {
    int bins = 1 << int(flatHeader(sm, WAVELIT_FLAT_BIN_LEVEL));
    vec2 p = octToSquare(axisLocal);
    int bx = min(int(p.x * float(bins)), bins - 1), by = min(int(p.y * float(bins)), bins - 1);
    uint at = sm.tableOffset + WAVELIT_FLAT_HEADER_WORDS + WAVELIT_FLAT_BIN_WORDS * uint(by * bins + bx);
    k = int(samplerWords[at + WAVELIT_FLAT_BIN_K]);
    ox = int(samplerWords[at + WAVELIT_FLAT_BIN_OX]);
    oy = int(samplerWords[at + WAVELIT_FLAT_BIN_OY]);
    factor = samplerWords[at + WAVELIT_FLAT_BIN_FACTOR];
}

// Where factor `factor`'s node words start (its first node's word index) and how many nodes.
void flatFactorNodes(SamplerMaterial sm, uint factor, out uint firstNode, out uint nodeCount) {
    uint at = sm.tableOffset + WAVELIT_FLAT_HEADER_WORDS +
              WAVELIT_FLAT_BIN_WORDS * flatHeader(sm, WAVELIT_FLAT_BIN_COUNT) +
              WAVELIT_FLAT_FACTOR_WORDS * factor;
    firstNode = samplerWords[at + WAVELIT_FLAT_FACTOR_FIRST_NODE];
    nodeCount = samplerWords[at + WAVELIT_FLAT_FACTOR_NODE_COUNT];
}

// The factor's root scaling coefficient F0(0,0).
float flatScaling(SamplerMaterial sm, uint factor) {
    return uintBitsToFloat(samplerWords[sm.scalingOffset + factor]);
}

// Node `node` (relative to the factor's first) of a factor: its three Haar details and the index
// of child c (-1: none).
uint flatNodeBase(SamplerMaterial sm, uint firstNode, int node) {
    return sm.nodeOffset + (firstNode + uint(node)) * WAVELIT_FLAT_NODE_WORDS;
}
vec3 flatNodeDetails(uint base) {
    return vec3(uintBitsToFloat(samplerWords[base + WAVELIT_FLAT_NODE_DETAIL]),
                uintBitsToFloat(samplerWords[base + WAVELIT_FLAT_NODE_DETAIL + 1u]),
                uintBitsToFloat(samplerWords[base + WAVELIT_FLAT_NODE_DETAIL + 2u]));
}
int flatNodeChild(uint base, int c) {
    return int(samplerWords[base + WAVELIT_FLAT_NODE_CHILD + uint(c)]);
}

#endif
