#include "wavelet/factor_product_tree.h"

#include "util/check.h"
#include "wavelet/product.h"

namespace wavelit::wavelet {

FactorProductTree::FactorProductTree(std::vector<SparseHaar> factors) {
    WAVELIT_CHECK(!factors.empty());
    for (const SparseHaar& f : factors)
        WAVELIT_CHECK(f.level == factors[0].level);
    m_leafNode.resize(factors.size());
    m_nodes.reserve(2 * factors.size());
    build(factors, 0, factors.size(), -1);
    update();
}

int FactorProductTree::build(std::vector<SparseHaar>& factors, size_t begin, size_t end,
                             int parent) {
    const int self = int(m_nodes.size());
    m_nodes.emplace_back();
    m_nodes[size_t(self)].parent = parent;
    if (end - begin == 1) {
        m_nodes[size_t(self)].value = std::move(factors[begin]);
        m_leafNode[begin] = self;
        return self;
    }
    const size_t mid = begin + (end - begin + 1) / 2;
    const int left = build(factors, begin, mid, self);
    const int right = build(factors, mid, end, self);
    m_nodes[size_t(self)].left = left;
    m_nodes[size_t(self)].right = right;
    m_nodes[size_t(self)].revision = 0; // never computed: stale
    return self;
}

void FactorProductTree::replace(size_t j, SparseHaar factor) {
    WAVELIT_CHECK(j < m_leafNode.size());
    Node& leaf = m_nodes[size_t(m_leafNode[j])];
    WAVELIT_CHECK(factor.level == leaf.value.level);
    leaf.value = std::move(factor);
    ++leaf.revision;
}

bool FactorProductTree::nodeStale(const Node& node) const {
    if (node.left < 0)
        return node.parent < 0 && node.seenLeft != node.revision; // single-leaf root
    return node.revision == 0 || node.seenLeft != m_nodes[size_t(node.left)].revision ||
           node.seenRight != m_nodes[size_t(node.right)].revision;
}

bool FactorProductTree::stale() const {
    for (const Node& node : m_nodes)
        if (nodeStale(node))
            return true;
    return false;
}

size_t FactorProductTree::recompute(int index) {
    Node& node = m_nodes[size_t(index)];
    if (node.left < 0) {
        if (node.parent < 0 && node.seenLeft != node.revision) {
            const SparseHaar* one[] = {&node.value};
            node.pyramid = sparseProduct(one);
            node.seenLeft = node.revision;
        }
        return 0;
    }
    size_t products = recompute(node.left) + recompute(node.right);
    if (!nodeStale(node))
        return products;
    const Node& l = m_nodes[size_t(node.left)];
    const Node& r = m_nodes[size_t(node.right)];
    const SparseHaar* pair[] = {&l.value, &r.value};
    node.pyramid = wavelet::product(pair); // dense or sparse path by density (product.h)
    node.value = node.pyramid.toSparseHaar();
    node.seenLeft = l.revision;
    node.seenRight = r.revision;
    ++node.revision;
    return products + 1;
}

size_t FactorProductTree::update() {
    const size_t products = recompute(0);
    m_totalProducts += products;
    return products;
}

SparseHaar FactorProductTree::productExcept(size_t j) const {
    WAVELIT_CHECK(j < m_leafNode.size());
    std::vector<const SparseHaar*> siblings;
    for (int node = m_leafNode[j]; m_nodes[size_t(node)].parent >= 0;
         node = m_nodes[size_t(node)].parent) {
        const Node& p = m_nodes[size_t(m_nodes[size_t(node)].parent)];
        siblings.push_back(&m_nodes[size_t(p.left == node ? p.right : p.left)].value);
    }
    const SparseHaar& f = factor(j);
    if (siblings.empty())
        return SparseHaar::constant(f.level, 1.0); // the product of nothing is 1
    return wavelet::product(siblings).toSparseHaar();
}

double FactorProductTree::integralWith(size_t j, const SparseHaar& g) const {
    return innerProduct(productExcept(j), g);
}

} // namespace wavelit::wavelet
