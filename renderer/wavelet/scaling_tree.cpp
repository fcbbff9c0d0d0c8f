#include "wavelet/scaling_tree.h"

#include "util/check.h"

#include <cmath>
#include <deque>

namespace wavelit::wavelet {
namespace {

void fillGrid(const ScalingTree& tree, int node, int l, int x, int y, SquareGrid& grid) {
    const PyramidNode& p = tree.nodes[size_t(node)];
    if (p.firstChild < 0) {
        // Constant square: texel value = average = 2^l F0.
        const double value = std::ldexp(p.value, l);
        const int span = 1 << (tree.level - l);
        for (int j = 0; j < span; ++j)
            for (int i = 0; i < span; ++i)
                grid.at(x * span + i, y * span + j) = value;
        return;
    }
    for (int c = 0; c < 4; ++c)
        fillGrid(tree, p.firstChild + c, l + 1, 2 * x + (c & 1), 2 * y + (c >> 1), grid);
}

} // namespace

double ScalingTree::valueAt(int l, int x, int y) const {
    WAVELIT_CHECK(l >= 0 && l <= level);
    int node = 0;
    for (int k = 0; k < l; ++k) {
        const PyramidNode& p = nodes[size_t(node)];
        if (p.firstChild < 0)
            return std::ldexp(p.value, -(l - k)); // constant below: halves per level
        const int shift = l - k - 1;
        const int c = ((x >> shift) & 1) | (((y >> shift) & 1) << 1);
        node = p.firstChild + c;
    }
    return nodes[size_t(node)].value;
}

SquareGrid ScalingTree::toGrid() const {
    SquareGrid grid(level);
    if (!nodes.empty())
        fillGrid(*this, 0, 0, 0, 0, grid);
    return grid;
}

SparseHaar ScalingTree::toSparseHaar() const {
    SparseHaar out;
    out.level = level;
    out.scaling = integral();
    if (nodes.empty() || nodes[0].firstChild < 0)
        return out;
    struct Item {
        int node, l, x, y, parent, slot;
    };
    std::deque<Item> queue{{0, 0, 0, 0, -1, 0}};
    while (!queue.empty()) {
        Item it = queue.front();
        queue.pop_front();
        const PyramidNode& p = nodes[size_t(it.node)];
        double child[4], s;
        for (int c = 0; c < 4; ++c)
            child[c] = nodes[size_t(p.firstChild + c)].value;
        SparseNode sn;
        sn.level = int16_t(it.l);
        sn.x = it.x;
        sn.y = it.y;
        haarAnalyze(child, s, sn.detail);
        const int self = int(out.nodes.size());
        out.nodes.push_back(sn);
        if (it.parent >= 0)
            out.nodes[size_t(it.parent)].child[it.slot] = self;
        for (int c = 0; c < 4; ++c) {
            const int cn = p.firstChild + c;
            if (nodes[size_t(cn)].firstChild >= 0)
                queue.push_back({cn, it.l + 1, 2 * it.x + (c & 1), 2 * it.y + (c >> 1), self, c});
        }
    }
    return out;
}

ScalingTree ScalingTree::fromGrid(const SquareGrid& grid) {
    const int n = grid.level;
    // Per-level scaling coefficients, finest first (eq 12), then parents by analysis.
    std::vector<std::vector<double>> levels(size_t(n) + 1);
    levels[size_t(n)] = grid.values;
    const double finest = std::ldexp(1.0, -n);
    for (double& v : levels[size_t(n)])
        v *= finest;
    for (int l = n - 1; l >= 0; --l) {
        const int side = 1 << l, cs = side * 2;
        const auto& c = levels[size_t(l + 1)];
        auto& p = levels[size_t(l)];
        p.resize(size_t(side) * side);
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                p[size_t(y) * side + x] =
                    0.5 *
                    (c[size_t(2 * y) * cs + 2 * x] + c[size_t(2 * y) * cs + 2 * x + 1] +
                     c[size_t(2 * y + 1) * cs + 2 * x] + c[size_t(2 * y + 1) * cs + 2 * x + 1]);
    }
    // Breadth-first layout: children of consecutive nodes are consecutive blocks of four.
    ScalingTree tree;
    tree.level = n;
    size_t total = 0;
    for (int l = 0; l <= n; ++l)
        total += size_t(1) << (2 * l);
    tree.nodes.reserve(total);
    struct Item {
        int l, x, y;
    };
    std::vector<Item> current{{0, 0, 0}}, next;
    tree.nodes.push_back({levels[0][0], -1});
    size_t levelStart = 0;
    for (int l = 0; l < n; ++l) {
        next.clear();
        const int cs = 2 << l;
        for (size_t i = 0; i < current.size(); ++i) {
            tree.nodes[levelStart + i].firstChild = int32_t(tree.nodes.size());
            for (int c = 0; c < 4; ++c) {
                Item ch{l + 1, 2 * current[i].x + (c & 1), 2 * current[i].y + (c >> 1)};
                tree.nodes.push_back({levels[size_t(l + 1)][size_t(ch.y) * cs + ch.x], -1});
                next.push_back(ch);
            }
        }
        levelStart += current.size();
        current.swap(next);
    }
    return tree;
}

} // namespace wavelit::wavelet
