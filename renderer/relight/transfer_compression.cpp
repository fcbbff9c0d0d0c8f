#include "relight/transfer_compression.h"

#include "wavelet/haar.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace wavelit::relight {
namespace {

// The K largest of the Haar coefficients `coeffs` (index 0 the scaling coefficient, always kept)
// by luminance-weighted magnitude, into `out`.
template <typename Value, typename Score, typename ToRgb>
void keepLargest(const std::vector<Value>& coeffs, size_t keep, SparseTransfer& out, Score score, ToRgb toRgb) {
    thread_local std::vector<std::pair<double, uint32_t>> ranked;
    ranked.clear();
    for (size_t i = 1; i < coeffs.size(); ++i) {
        const double sc = score(coeffs[i]);
        if (sc > 0.0) ranked.push_back({-sc, uint32_t(i)}); // ascending = largest first
    }
    const size_t details = keep > 1 ? keep - 1 : 0;
    if (ranked.size() > details) {
        std::nth_element(ranked.begin(), ranked.begin() + std::ptrdiff_t(details), ranked.end());
        ranked.resize(details);
    }
    out.index.clear();
    out.index.push_back(0);
    for (const auto& r : ranked) out.index.push_back(uint16_t(r.second));
    std::sort(out.index.begin(), out.index.end());
    out.value.resize(out.index.size());
    for (size_t k = 0; k < out.index.size(); ++k) out.value[k] = toRgb(coeffs[out.index[k]]);
}

} // namespace

// compress() for a grey T (a grey-affine BRDF's f(white) and f(black), ResolvedMaterial::oneEval):
// one channel instead of three, a third of the transform (docs/relighting.md §7.0b). The channels
// of the RGB transform are independent, so each coefficient is the same; the ranking weighs a
// grey coefficient by the sum of the luminance weights, the same order.
void compressGrey(std::vector<double>& texels, int level, size_t keep, SparseTransfer& out) {
    thread_local std::vector<double> parent, coeffs;
    const size_t count = texels.size();
    coeffs.assign(count, 0.0);
    for (int l = level - 1; l >= 0; --l) {
        const int side = 1 << l, childSide = side * 2;
        parent.assign(size_t(side) * size_t(side), 0.0);
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
    coeffs.assign(count, glm::dvec3(0.0));
    for (int l = level - 1; l >= 0; --l) {
        const int side = 1 << l, childSide = side * 2;
        parent.assign(size_t(side) * size_t(side), glm::dvec3(0.0));
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
