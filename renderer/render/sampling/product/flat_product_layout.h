// The word layout of MaterialProductTables::flatten() (docs/wavelet-sampler.md "Flat export"),
// written once: flatten(), bytes() and unflattenFactor() use it on the CPU, and the shaders get it
// as #defines (render/gpu/sampler_shader_defines.h). All counts and offsets are in 32-bit words.
//   header   kFlatHeaderWords words: magic, binLevel, productLevel, binCount, factorCount;
//            then per bin kFlatBinWords (k, ox, oy, factor), then per factor kFlatFactorWords
//            (firstNode, nodeCount)
//   nodes    kFlatNodeWords per node: level, x, y, 3 float details, 4 int32 children
#pragma once

namespace wavelit::render::flat_layout {

inline constexpr int kHeaderWords = 5;
inline constexpr int kMagic = 0, kBinLevel = 1, kProductLevel = 2, kBinCount = 3, kFactorCount = 4;

inline constexpr int kBinWords = 4;
inline constexpr int kBinK = 0, kBinOx = 1, kBinOy = 2, kBinFactor = 3;

inline constexpr int kFactorWords = 2;
inline constexpr int kFactorFirstNode = 0, kFactorNodeCount = 1;

inline constexpr int kNodeWords = 10;
inline constexpr int kNodeLevel = 0, kNodeX = 1, kNodeY = 2, kNodeDetail = 3, kNodeChild = 6;

// Word offset (in the header) of bin `bin`'s words and of factor `factor`'s words.
constexpr int binWordsAt(int bin) { return kHeaderWords + kBinWords * bin; }
constexpr int factorWordsAt(int binCount, int factor) {
    return kHeaderWords + kBinWords * binCount + kFactorWords * factor;
}

} // namespace wavelit::render::flat_layout
