#include "wavelet/hierarchical_sampler.h"

#include <algorithm>
#include <cmath>

namespace wavelit::wavelet {
namespace {

// Largest double below 1: rescaled numbers stay in [0, 1) despite rounding in the division.
constexpr double kOneMinusEpsilon = 0x1.fffffffffffffp-1;

// A split is stored as the smaller of the two probabilities, sign marking which half it belongs
// to (negative: the second half). Storing p0 itself would make 1 - p0 lose all its digits when p0
// is near 1 (a sun taking 0.999999 of the mass leaves the sky a probability off by ~6%); this way
// both halves keep float's 2^-24 relative precision.
struct Split {
    double p0, p1;
};
inline Split decode(float s) {
    if (std::signbit(s))
        return {1.0 - double(-s), double(-s)};
    return {double(s), 1.0 - double(s)};
}
inline float encode(double first, double second) {
    const double whole = first + second;
    if (!(whole > 0.0))
        return 0.5f; // no mass: uniform (only reached by sampleWithin)
    return first <= second ? float(first / whole) : -float(second / whole);
}

// Picks the first half with probability p0 and rescales u into [0, 1).
inline int choose(float split, double& u, double& probability) {
    const Split p = decode(split);
    if (u < p.p0) {
        u = std::min(u / p.p0, kOneMinusEpsilon);
        probability *= p.p0;
        return 0;
    }
    u = std::min((u - p.p0) / p.p1, kOneMinusEpsilon);
    probability *= p.p1;
    return 1;
}

} // namespace

util::Result<HierarchicalSampler> HierarchicalSampler::build(const ScalingTree& tree) {
    const size_t count = tree.nodes.size();
    std::vector<int> level(count, 0);
    for (size_t i = 0; i < count; ++i) {
        if (!std::isfinite(tree.nodes[i].value))
            return util::makeError(util::ErrorKind::Invalid, "", "non-finite scaling coefficient");
        if (tree.nodes[i].firstChild >= 0)
            for (int c = 0; c < 4; ++c)
                level[size_t(tree.nodes[i].firstChild + c)] = level[i] + 1;
    }
    // Clamped masses bottom-up (children always follow their parent in both tree layouts):
    // a leaf's mass is its integral 4^-l * 2^l F0 = 2^-l F0, clamped to 0.
    std::vector<double> mass(count, 0.0);
    for (size_t i = count; i-- > 0;) {
        const PyramidNode& p = tree.nodes[i];
        if (p.firstChild < 0) {
            mass[i] = std::max(0.0, std::ldexp(p.value, -level[i]));
        } else {
            const size_t c = size_t(p.firstChild);
            mass[i] = mass[c] + mass[c + 1] + mass[c + 2] + mass[c + 3];
        }
    }
    if (!std::isfinite(mass[0]))
        return util::makeError(util::ErrorKind::Invalid, "",
                               "the function's integral overflows double precision");
    if (!(mass[0] > 0.0))
        return util::makeError(
            util::ErrorKind::Invalid, "",
            "all-zero product: nothing to sample (fall back to another sampler)");
    HierarchicalSampler s;
    s.m_level = tree.level;
    s.m_clampedIntegral = mass[0];
    s.m_nodes.resize(count);
    for (size_t i = 0; i < count; ++i) {
        const PyramidNode& p = tree.nodes[i];
        Node& n = s.m_nodes[i];
        n.firstChild = p.firstChild;
        if (p.firstChild < 0)
            continue;
        const size_t c = size_t(p.firstChild);
        const double top = mass[c] + mass[c + 1], bottom = mass[c + 2] + mass[c + 3];
        n.py0 = encode(top, bottom);
        n.px0y0 = encode(mass[c], mass[c + 1]);
        n.px0y1 = encode(mass[c + 2], mass[c + 3]);
    }
    return s;
}

// The descent path to the leaf containing a point: the splits used and the child taken.
struct HierarchicalSampler::PathStep {
    Split py, px;
    int cx, cy;
};

namespace {

glm::dvec2 localCoordinates(SquareCell cell, glm::dvec2 point) {
    const double scale = std::ldexp(1.0, cell.level);
    return {point.x * scale - cell.x, point.y * scale - cell.y};
}

glm::dvec2 globalCoordinates(SquareCell cell, glm::dvec2 local) {
    const double side = std::ldexp(1.0, -cell.level);
    return {(cell.x + local.x) * side, (cell.y + local.y) * side};
}

bool insideUnitSquare(glm::dvec2 p) {
    return p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0;
}

} // namespace

SquareCell HierarchicalSampler::chooseLeaf(int node, SquareCell cell, glm::dvec2& u,
                                           double& probability) const {
    while (m_nodes[size_t(node)].firstChild >= 0) {
        const Node& n = m_nodes[size_t(node)];
        const int cy = choose(n.py0, u.y, probability);
        const int cx = choose(cy == 0 ? n.px0y0 : n.px0y1, u.x, probability);
        node = n.firstChild + cx + 2 * cy;
        cell = {cell.level + 1, 2 * cell.x + cx, 2 * cell.y + cy};
    }
    return cell;
}

SquareCell HierarchicalSampler::locate(int node, SquareCell cell, glm::dvec2 point,
                                       double& probability, std::vector<PathStep>* path) const {
    while (m_nodes[size_t(node)].firstChild >= 0) {
        const Node& n = m_nodes[size_t(node)];
        const double scale = std::ldexp(1.0, cell.level + 1);
        const int cx = std::clamp(int(point.x * scale) - 2 * cell.x, 0, 1);
        const int cy = std::clamp(int(point.y * scale) - 2 * cell.y, 0, 1);
        const Split py = decode(n.py0), px = decode(cy == 0 ? n.px0y0 : n.px0y1);
        probability *= (cy == 0 ? py.p0 : py.p1) * (cx == 0 ? px.p0 : px.p1);
        if (path)
            path->push_back({py, px, cx, cy});
        node = n.firstChild + cx + 2 * cy;
        cell = {cell.level + 1, 2 * cell.x + cx, 2 * cell.y + cy};
    }
    return cell;
}

// Undoes each level's rescaling from the leaf up: u is the number pair that was left at the leaf.
glm::dvec2 HierarchicalSampler::unwind(const std::vector<PathStep>& path, glm::dvec2 u) {
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
        u.x = it->cx == 0 ? u.x * it->px.p0 : it->px.p0 + u.x * it->px.p1;
        u.y = it->cy == 0 ? u.y * it->py.p0 : it->py.p0 + u.y * it->py.p1;
    }
    return u;
}

int HierarchicalSampler::findNode(SquareCell cell, int& reachedLevel) const {
    int node = 0;
    reachedLevel = 0;
    while (reachedLevel < cell.level && m_nodes[size_t(node)].firstChild >= 0) {
        const int shift = cell.level - reachedLevel - 1;
        const int c = ((cell.x >> shift) & 1) | (((cell.y >> shift) & 1) << 1);
        node = m_nodes[size_t(node)].firstChild + c;
        ++reachedLevel;
    }
    return node;
}

SquareSample HierarchicalSampler::sample(glm::dvec2 u) const {
    double probability = 1.0;
    const SquareCell leaf = chooseLeaf(0, {}, u, probability);
    return {globalCoordinates(leaf, u), std::ldexp(probability, 2 * leaf.level)};
}

double HierarchicalSampler::pdf(glm::dvec2 point) const {
    double probability = 0.0;
    const SquareCell leaf = leafAt(point, probability);
    return std::ldexp(probability, 2 * leaf.level);
}

glm::dvec2 HierarchicalSampler::invert(glm::dvec2 point) const {
    std::vector<PathStep> path;
    double probability = 1.0;
    const SquareCell leaf = locate(0, {}, point, probability, &path);
    return unwind(path, localCoordinates(leaf, point));
}

SquareCell HierarchicalSampler::sampleLeaf(glm::dvec2& u, double& probability) const {
    probability = 1.0;
    return chooseLeaf(0, {}, u, probability);
}

SquareCell HierarchicalSampler::leafAt(glm::dvec2 point, double& probability) const {
    probability = 0.0;
    if (!insideUnitSquare(point))
        return {};
    probability = 1.0;
    return locate(0, {}, point, probability, nullptr);
}

// Inside a cell the walks start at the cell's node with probability 1, so a leaf's probability
// over its area is the conditional density (it integrates to 1 over the cell). Where this quadtree
// is constant over a larger square than the cell, the cell is uniform: density 1 / area.
SquareSample HierarchicalSampler::sampleWithin(SquareCell cell, glm::dvec2 u) const {
    int reached = 0;
    const int node = findNode(cell, reached);
    if (reached < cell.level)
        return {globalCoordinates(cell, u), std::ldexp(1.0, 2 * cell.level)};
    double probability = 1.0;
    const SquareCell leaf = chooseLeaf(node, cell, u, probability);
    return {globalCoordinates(leaf, u), std::ldexp(probability, 2 * leaf.level)};
}

double HierarchicalSampler::pdfWithin(SquareCell cell, glm::dvec2 point) const {
    if (!insideUnitSquare(localCoordinates(cell, point)))
        return 0.0;
    int reached = 0;
    const int node = findNode(cell, reached);
    if (reached < cell.level)
        return std::ldexp(1.0, 2 * cell.level);
    double probability = 1.0;
    const SquareCell leaf = locate(node, cell, point, probability, nullptr);
    return std::ldexp(probability, 2 * leaf.level);
}

glm::dvec2 HierarchicalSampler::invertAbove(glm::dvec2 point, glm::dvec2 uInLeaf) const {
    std::vector<PathStep> path;
    double probability = 1.0;
    locate(0, {}, point, probability, &path);
    return unwind(path, uInLeaf);
}

glm::dvec2 HierarchicalSampler::invertWithin(SquareCell cell, glm::dvec2 point) const {
    int reached = 0;
    const int node = findNode(cell, reached);
    if (reached < cell.level)
        return localCoordinates(cell, point);
    std::vector<PathStep> path;
    double probability = 1.0;
    const SquareCell leaf = locate(node, cell, point, probability, &path);
    return unwind(path, localCoordinates(leaf, point));
}

} // namespace wavelit::wavelet
