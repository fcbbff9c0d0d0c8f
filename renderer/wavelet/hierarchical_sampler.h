// HierarchicalSampler: draws points in the unit square from a function given by its scaling-
// coefficient quadtree, by the paper's top-down descent (§3.3, eqs 14-17), with an exact pdf.
//
// The distribution sampled is the function's reconstruction clamped to 0 and renormalised:
// truncated wavelets make some reconstructed values (and so scaling coefficients) negative, and a
// descent on raw coefficients would use meaningless or negative probabilities. The tables are
// built bottom-up from clamped leaf masses in double, then stored as float conditional
// probabilities (each kept to float's relative precision, also near 0 and 1); the pdf returned
// is that of the float tables, i.e. exact for what is sampled (architecture.md §4: the estimator must
// divide by the pdf of what was actually sampled).
//
// Each descent step picks the row (y half) with u2 using the marginal, then the column with u1
// given the row, and rescales both numbers, so the warp is a bijection on [0,1)^2 that keeps
// stratification and can be inverted. Measures: pdf is per unit-square area (divide by the
// parameterisation's Jacobian d(omega)/dA for solid angle: 4 pi for the octahedral map).
// Thread-safety: const methods are safe to call concurrently.
#pragma once

#include "util/result.h"
#include "wavelet/scaling_tree.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace wavelit::wavelet {

struct SquareSample {
    glm::dvec2 point{0.0};
    double pdf = 0.0; // unit-square measure
};

// A square of the quadtree: level l, position (x, y) in [0, 2^l)^2.
struct SquareCell {
    int level = 0, x = 0, y = 0;
};

class HierarchicalSampler {
public:
    // Invalid error when a value is NaN/Inf; Invalid error "all-zero" when the clamped function
    // has no positive mass, so the caller can fall back to another sampler.
    static util::Result<HierarchicalSampler> build(const ScalingTree& tree);

    SquareSample sample(glm::dvec2 u) const;
    double pdf(glm::dvec2 point) const; // 0 outside [0,1)^2
    glm::dvec2 invert(glm::dvec2 point) const;
    // Inverses of the refinement pieces: the numbers that, left at the leaf containing `point`,
    // the descent would have been given (invertAbove), and the numbers sampleWithin(cell, u)
    // needs to produce `point` (invertWithin).
    glm::dvec2 invertAbove(glm::dvec2 point, glm::dvec2 uInLeaf) const;
    glm::dvec2 invertWithin(SquareCell cell, glm::dvec2 point) const;

    // For refinement (refined_sampler.h): descend to a leaf of this quadtree, returning the leaf
    // cell, its probability, and in u the rescaled numbers left for use inside it.
    SquareCell sampleLeaf(glm::dvec2& u, double& probability) const;
    SquareCell leafAt(glm::dvec2 point, double& probability) const;
    // Sampling restricted to `cell` (this quadtree's conditional distribution inside it; uniform
    // where the cell or its sub-square has no mass). pdf is the conditional density, per unit area.
    SquareSample sampleWithin(SquareCell cell, glm::dvec2 u) const;
    double pdfWithin(SquareCell cell, glm::dvec2 point) const;

    int level() const { return m_level; }
    double clampedIntegral() const { return m_clampedIntegral; } // integral of max(0, f)
    size_t nodeCount() const { return m_nodes.size(); }

    // The float tables, e.g. for upload to a GPU (16 bytes per node): a node's children are
    // firstChild + 0..3 (x-major), -1 for a leaf. Each split stores the smaller of its two
    // probabilities, negative (sign bit set) when it belongs to the second half: P(first) = s for
    // s with a clear sign bit, else 1 - |s|. So both halves keep float's relative precision.
    struct TableNode {
        float py0 = 0.5f;   // top row vs bottom row
        float px0y0 = 0.5f; // left vs right, given the top row
        float px0y1 = 0.5f; // left vs right, given the bottom row
        int32_t firstChild = -1;
    };
    const std::vector<TableNode>& table() const { return m_nodes; }

private:
    using Node = TableNode;
    struct PathStep;
    // Descends from `node` (square `cell`) to a leaf, choosing children with u (rescaled in place)
    // and multiplying `probability` by each choice's probability.
    SquareCell chooseLeaf(int node, SquareCell cell, glm::dvec2& u, double& probability) const;
    // The same walk guided by a point inside `cell`, recording the path when asked.
    SquareCell locate(int node, SquareCell cell, glm::dvec2 point, double& probability,
                      std::vector<PathStep>* path) const;
    static glm::dvec2 unwind(const std::vector<PathStep>& path, glm::dvec2 u);
    // The node of `cell`, or of its deepest ancestor when the tree is constant above it.
    int findNode(SquareCell cell, int& reachedLevel) const;

    std::vector<Node> m_nodes;
    int m_level = 0;
    double m_clampedIntegral = 0.0;
};

} // namespace wavelit::wavelet
