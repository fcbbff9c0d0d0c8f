// FactorProductTree: the factor cache of architecture.md §4 / paper §4 (eqs 24-27). m factors on one
// 2^n square are the leaves of a segment tree whose inner nodes hold the exact product of their
// two children (wavelet products, product.h, each path picked by density). Replacing factor j (a
// light moved, the environment rotated) invalidates only the nodes on j's path, so update()
// recomputes at most ceil(log2 m) pairwise products instead of m - 1.
//
// Staleness is by revision numbers: every node has a revision that increases when its value
// changes, and an inner node remembers the revisions of its children it was computed from; it is
// stale iff one differs. Several replacements may be batched before one update().
// The paper's <T, F_j> (eq 25) is integralWith(j, G): T = product of all factors but j, built
// from the siblings on j's path. Products are exact (no truncation of partial products), so the
// root equals a full recomputation bit for bit when computed in the same tree order.
// Not thread-safe: one owner (the render thread's factor cache) updates it.
#pragma once

#include "wavelet/scaling_tree.h"
#include "wavelet/sparse_haar.h"

#include <cstdint>
#include <vector>

namespace wavelit::wavelet {

class FactorProductTree {
public:
    // At least one factor, all of the same level. Builds every product (m - 1 of them).
    explicit FactorProductTree(std::vector<SparseHaar> factors);

    size_t factorCount() const { return m_leafNode.size(); }
    const SparseHaar& factor(size_t j) const { return m_nodes[size_t(m_leafNode[j])].value; }
    uint64_t factorRevision(size_t j) const { return m_nodes[size_t(m_leafNode[j])].revision; }

    // Replaces factor j and bumps its revision; the product is stale until update().
    void replace(size_t j, SparseHaar factor);
    bool stale() const;
    // Recomputes the stale nodes bottom-up; returns the number of pairwise products computed.
    size_t update();

    // The product of all factors (call update() first after replacements).
    const SparseHaar& product() const { return m_nodes[0].value; }
    const ScalingTree& productPyramid() const { return m_nodes[0].pyramid; }
    double integral() const { return m_nodes[0].value.scaling; }

    // Product of every factor except j: the siblings along j's path, in one multi-factor product.
    SparseHaar productExcept(size_t j) const;
    // <T, G> with T = productExcept(j): the integral the product would have with factor j = G.
    double integralWith(size_t j, const SparseHaar& g) const;

    size_t totalProducts() const { return m_totalProducts; }

private:
    struct Node {
        int left = -1, right = -1; // -1: leaf
        int parent = -1;
        uint64_t revision = 1;
        uint64_t seenLeft = 0, seenRight = 0;
        SparseHaar value;
        ScalingTree pyramid; // inner nodes and a single-leaf root: the product's pyramid
    };
    int build(std::vector<SparseHaar>& factors, size_t begin, size_t end, int parent);
    bool nodeStale(const Node& node) const;
    size_t recompute(int node);

    std::vector<Node> m_nodes;
    std::vector<int> m_leafNode;
    size_t m_totalProducts = 0;
};

} // namespace wavelit::wavelet
