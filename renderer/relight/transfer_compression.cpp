#include "relight/transfer_compression.h"

#include "wavelet/haar.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <functional>
#include <cmath>
#include <utility>

namespace wavelit::relight {
namespace {

// The K largest of the Haar coefficients `coeffs` (index 0 the scaling coefficient, always kept)
// by luminance-weighted magnitude, into `out`: the `keep` - 1 largest positive scores, ties to the
// lower index (what an nth_element over (-score, index) pairs selected before §7.0f). Found as a
// threshold instead — the (keep - 1)-th largest score, by its exponent's bucket in a histogram of
// the scores' bit patterns (which order positive doubles as the doubles do), then nth_element
// within that bucket — and one branch-free scan in index order, so the kept indices come out
// sorted: the pairs' selection and the index sort were ~30% of a roughness edit, and the
// branches of a plain nth_element over the patterns most of what was left (§7.0f).
template <typename Value, typename Score, typename ToRgb>
void keepLargest(const std::vector<Value>& coeffs, size_t keep, SparseTransfer& out, Score score, ToRgb toRgb) {
    thread_local std::vector<uint64_t> keys, bucket;
    thread_local std::array<uint32_t, 2048> histogram; // by the pattern's top 12 bits (sign 0, exponent)
    const size_t count = coeffs.size();
    keys.resize(count);
    histogram.fill(0);
    uint64_t maxKey = 0;
    size_t positives = 0;
    for (size_t i = 1; i < count; ++i) {
        const double sc = score(coeffs[i]);
        // 0 for no score (0 or NaN): below every positive score's pattern.
        const uint64_t key = sc > 0.0 ? std::bit_cast<uint64_t>(sc) : 0;
        keys[i] = key;
        ++histogram[key >> 52];
        maxKey = std::max(maxKey, key);
        positives += key != 0;
    }
    const size_t details = keep > 1 ? keep - 1 : 0;
    uint64_t threshold = 1;         // keep every key above it (1: every positive score) ...
    size_t atThreshold = positives; // ... and this many equal to it, lowest index first
    bool allTies = true;            // atThreshold is every key equal to it: keep key >= threshold
    if (positives > details) {
        if (details == 0) threshold = ~uint64_t(0);
        else {
            // The exponent bucket holding the details-th largest key, and how many lie above it.
            size_t above = 0;
            uint64_t e = maxKey >> 52;
            while (above + histogram[e] < details) above += histogram[e--];
            bucket.resize(histogram[e] + 1); // + one spare write
            size_t n = 0;
            for (size_t i = 1; i < count; ++i) {
                bucket[n] = keys[i];
                n += (keys[i] >> 52) == e && keys[i] != 0; // bucket 0 also holds the zeros
            }
            bucket.resize(n);
            const auto nth = bucket.begin() + std::ptrdiff_t(details - above - 1);
            std::nth_element(bucket.begin(), nth, bucket.end(), std::greater<>());
            threshold = *nth;
            for (auto it = bucket.begin(); it != nth; ++it) above += *it > threshold;
            atThreshold = details - above;
            size_t equal = 0; // every key equal to the threshold lies in its bucket
            for (const uint64_t key : bucket) equal += key == threshold;
            allTies = equal == atThreshold;
        }
    }
    out.index.resize(std::min(details, positives) + 2); // + the scaling coefficient, + one spare write
    uint16_t* index = out.index.data();
    index[0] = 0;
    size_t kept = 1;
    if (allTies) // the usual case: one compare, no chain through a tie count
        for (size_t i = 1; i < count; ++i) {
            index[kept] = uint16_t(i);
            kept += keys[i] >= threshold;
        }
    else
        for (size_t i = 1; i < count; ++i) {
            const uint64_t key = keys[i];
            const bool tie = key == threshold && atThreshold > 0;
            atThreshold -= tie;
            index[kept] = uint16_t(i);
            kept += key > threshold || tie;
        }
    out.index.resize(kept);
    out.value.resize(kept);
    for (size_t k = 0; k < kept; ++k) out.value[k] = toRgb(coeffs[out.index[k]]);
}

} // namespace

// compress() for a grey T (a grey-affine BRDF's f(white) and f(black), ResolvedMaterial::oneEval):
// one channel instead of three, a third of the transform (docs/relighting.md §7.0b). The channels
// of the RGB transform are independent, so each coefficient is the same; the ranking weighs a
// grey coefficient by the sum of the luminance weights, the same order.
void compressGrey(std::vector<double>& texels, int level, size_t keep, SparseTransfer& out) {
    thread_local std::vector<double> parent, coeffs;
    const size_t count = texels.size();
    coeffs.resize(count); // every entry is written below
    for (int l = level - 1; l >= 0; --l) {
        const int side = 1 << l, childSide = side * 2;
        parent.resize(size_t(side) * size_t(side));
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const size_t r0 = size_t(2 * y) * size_t(childSide), r1 = r0 + size_t(childSide);
                const size_t base = wavelet::detailIndex(l, x, y, 0);
                const double child[4] = {texels[r0 + size_t(2 * x)], texels[r0 + size_t(2 * x) + 1],
                                         texels[r1 + size_t(2 * x)], texels[r1 + size_t(2 * x) + 1]};
                double d[3];
                wavelet::haarAnalyze(child, parent[size_t(y) * size_t(side) + size_t(x)], d);
                coeffs[base] = d[0];
                coeffs[base + 1] = d[1];
                coeffs[base + 2] = d[2];
            }
        texels.swap(parent);
    }
    coeffs[0] = texels[0];
    keepLargest(coeffs, keep, out, [](double v) { return (0.2126 + 0.7152 + 0.0722) * std::abs(v); },
                [](double v) { return glm::vec3(float(v)); });
}

// Haar analysis of the texel values (already scaled to finest scaling coefficients) and the K
// largest coefficients. `texels` is clobbered.
void compress(std::vector<glm::dvec3>& texels, int level, size_t keep, SparseTransfer& out) {
    // Scratch buffers per worker thread: a material edit rebuilds T on thousands of points, and
    // allocating grids and pyramids for each cost as much as the transform.
    thread_local std::vector<glm::dvec3> parent, coeffs;
    const size_t count = texels.size();
    // wavelet::forwardHaar's nonstandard decomposition, the three channels in one pass.
    coeffs.resize(count); // every entry is written below
    for (int l = level - 1; l >= 0; --l) {
        const int side = 1 << l, childSide = side * 2;
        parent.resize(size_t(side) * size_t(side));
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const size_t r0 = size_t(2 * y) * size_t(childSide), r1 = r0 + size_t(childSide);
                const size_t base = wavelet::detailIndex(l, x, y, 0);
                for (int c = 0; c < 3; ++c) {
                    const double child[4] = {texels[r0 + size_t(2 * x)][c], texels[r0 + size_t(2 * x) + 1][c],
                                             texels[r1 + size_t(2 * x)][c], texels[r1 + size_t(2 * x) + 1][c]};
                    double d[3];
                    wavelet::haarAnalyze(child, parent[size_t(y) * size_t(side) + size_t(x)][c], d);
                    coeffs[base][c] = d[0];
                    coeffs[base + 1][c] = d[1];
                    coeffs[base + 2][c] = d[2];
                }
            }
        texels.swap(parent);
    }
    coeffs[0] = texels[0];
    keepLargest(
        coeffs, keep, out,
        [](const glm::dvec3& v) { return 0.2126 * std::abs(v.x) + 0.7152 * std::abs(v.y) + 0.0722 * std::abs(v.z); },
        [](const glm::dvec3& v) { return glm::vec3(v); });
}

// compress(), or compressGrey() when every texel is grey (a lambert's or any colour-linear
// BRDF's f(white) with grey visibility): the same coefficients in a third of the transform.
void compressMaybeGrey(std::vector<glm::dvec3>& texels, int level, size_t keep, SparseTransfer& out) {
    for (const glm::dvec3& v : texels)
        if (v.x != v.y || v.x != v.z) {
            compress(texels, level, keep, out);
            return;
        }
    thread_local std::vector<double> grey;
    grey.resize(texels.size());
    for (size_t i = 0; i < texels.size(); ++i) grey[i] = texels[i].x;
    compressGrey(grey, level, keep, out);
}

} // namespace wavelit::relight
