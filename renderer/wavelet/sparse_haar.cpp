#include "wavelet/sparse_haar.h"

#include "util/check.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>

namespace wavelit::wavelet {
namespace {

// Builds the breadth-first node array from a per-level "has detail at or below" pyramid.
// below[l] is a 2^l x 2^l row-major mask for levels 0..n-1.
SparseHaar buildFromMask(const HaarImage& image, const std::vector<std::vector<uint8_t>>& below,
                         const std::vector<uint8_t>& kept) {
    SparseHaar out;
    out.level = image.level;
    out.scaling = image.coeffs[0];
    if (image.level == 0 || !below[0][0])
        return out;
    struct Item {
        int l, x, y;
        int parent;
        int slot;
    };
    std::deque<Item> queue{{0, 0, 0, -1, 0}};
    while (!queue.empty()) {
        Item it = queue.front();
        queue.pop_front();
        SparseNode node;
        node.level = int16_t(it.l);
        node.x = it.x;
        node.y = it.y;
        for (int m = 0; m < 3; ++m) {
            size_t idx = detailIndex(it.l, it.x, it.y, m);
            node.detail[m] = kept[idx] ? image.coeffs[idx] : 0.0;
        }
        const int self = int(out.nodes.size());
        out.nodes.push_back(node);
        if (it.parent >= 0)
            out.nodes[size_t(it.parent)].child[it.slot] = self;
        const int cl = it.l + 1;
        if (cl >= image.level)
            continue;
        for (int c = 0; c < 4; ++c) {
            int cx = 2 * it.x + (c & 1), cy = 2 * it.y + (c >> 1);
            if (below[size_t(cl)][(size_t(cy) << cl) + size_t(cx)])
                queue.push_back({cl, cx, cy, self, c});
        }
    }
    return out;
}

SparseHaar buildKept(const HaarImage& image, const std::vector<uint8_t>& kept) {
    const int n = image.level;
    std::vector<std::vector<uint8_t>> below(size_t(std::max(n, 1)));
    for (int l = n - 1; l >= 0; --l) {
        const int side = 1 << l;
        below[size_t(l)].assign(size_t(side) * side, 0);
        for (int y = 0; y < side; ++y) {
            for (int x = 0; x < side; ++x) {
                bool any = false;
                for (int m = 0; m < 3; ++m)
                    any = any || kept[detailIndex(l, x, y, m)];
                if (l + 1 < n) {
                    const auto& c = below[size_t(l + 1)];
                    const size_t cs = size_t(side) * 2;
                    any = any || c[2 * y * cs + 2 * x] || c[2 * y * cs + 2 * x + 1] ||
                          c[(2 * y + 1) * cs + 2 * x] || c[(2 * y + 1) * cs + 2 * x + 1];
                }
                below[size_t(l)][size_t(y) * side + x] = any;
            }
        }
    }
    return buildFromMask(image, below, kept);
}

double jointDetails(const SparseHaar& f, int a, const SparseHaar& g, int b) {
    const SparseNode& na = f.nodes[size_t(a)];
    const SparseNode& nb = g.nodes[size_t(b)];
    double sum =
        na.detail[0] * nb.detail[0] + na.detail[1] * nb.detail[1] + na.detail[2] * nb.detail[2];
    for (int c = 0; c < 4; ++c)
        if (na.child[c] >= 0 && nb.child[c] >= 0)
            sum += jointDetails(f, na.child[c], g, nb.child[c]);
    return sum;
}

} // namespace

size_t SparseHaar::nonzeroCount() const {
    size_t count = scaling != 0.0 ? 1 : 0;
    for (const SparseNode& node : nodes)
        for (double d : node.detail)
            count += d != 0.0;
    return count;
}

HaarImage SparseHaar::toDense() const {
    HaarImage image;
    image.level = level;
    image.coeffs.assign(size_t(1) << (2 * level), 0.0);
    image.coeffs[0] = scaling;
    for (const SparseNode& node : nodes)
        for (int m = 0; m < 3; ++m)
            image.coeffs[detailIndex(node.level, node.x, node.y, m)] = node.detail[m];
    return image;
}

SparseHaar SparseHaar::constant(int n, double scaling) {
    SparseHaar out;
    out.level = n;
    out.scaling = scaling;
    return out;
}

SparseHaar sparsify(const HaarImage& image) {
    std::vector<uint8_t> kept(image.coeffs.size());
    for (size_t i = 1; i < kept.size(); ++i)
        kept[i] = image.coeffs[i] != 0.0;
    return buildKept(image, kept);
}

Truncation truncate(const HaarImage& image, size_t keep, Weighting weighting) {
    const size_t count = image.coeffs.size();
    std::vector<uint8_t> kept(count, 0);
    Truncation out;
    double total = 0.0;
    for (double c : image.coeffs)
        total += c * c;
    if (keep >= count) {
        for (size_t i = 1; i < count; ++i)
            kept[i] = image.coeffs[i] != 0.0;
    } else if (keep > 1) {
        std::vector<double> weight(count, 0.0);
        for (size_t i = 1; i < count; ++i) {
            double w = std::abs(image.coeffs[i]);
            if (weighting == Weighting::AreaWeighted)
                w = std::ldexp(w, -levelOfIndex(i));
            weight[i] = w;
        }
        std::vector<uint32_t> order(count - 1);
        std::iota(order.begin(), order.end(), 1u);
        auto larger = [&](uint32_t a, uint32_t b) {
            return weight[a] != weight[b] ? weight[a] > weight[b] : a < b;
        };
        std::nth_element(order.begin(), order.begin() + long(keep - 1), order.end(), larger);
        for (size_t i = 0; i < keep - 1; ++i)
            kept[order[i]] = image.coeffs[order[i]] != 0.0;
    }
    double dropped = 0.0;
    for (size_t i = 1; i < count; ++i)
        if (!kept[i])
            dropped += image.coeffs[i] * image.coeffs[i];
    out.coefficients = buildKept(image, kept);
    out.kept = out.coefficients.nonzeroCount();
    out.droppedL2 = std::sqrt(dropped);
    out.relativeL2 = total > 0.0 ? std::sqrt(dropped / total) : 0.0;
    return out;
}

double innerProduct(const SparseHaar& f, const SparseHaar& g) {
    WAVELIT_CHECK(f.level == g.level);
    double sum = f.scaling * g.scaling;
    if (f.root() >= 0 && g.root() >= 0)
        sum += jointDetails(f, 0, g, 0);
    return sum;
}

} // namespace wavelit::wavelet
