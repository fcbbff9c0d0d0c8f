// RefinedSampler: a coarse product sampler refined below its resolution by a finer
// single-factor pyramid (architecture.md §4.1, item 1).
//
// A 32^2 or 64^2 product of truncated factors cannot see a sun far smaller than its texels, and
// jittering uniformly inside a product leaf costs hundreds of times the variance. So at a product
// leaf the descent continues in the fine factor's (the full-resolution environment's) quadtree,
// restricted to that leaf: the other factors (the BRDF) are taken as constant inside it. The pdf
// stays exact: P(product leaf) x the fine factor's conditional density inside the leaf (uniform
// where the fine factor has no mass there). Both samplers must cover the same unit square; the
// fine one may be any level (>= the product's to be useful). Unit-square measure.
#pragma once

#include "wavelet/hierarchical_sampler.h"

namespace wavelit::wavelet {

class RefinedSampler {
public:
    // Both samplers are referenced, not copied: they must outlive this object.
    RefinedSampler(const HierarchicalSampler& product, const HierarchicalSampler& fine)
        : m_product(&product), m_fine(&fine) {}

    SquareSample sample(glm::dvec2 u) const {
        double leafProbability = 0.0;
        const SquareCell leaf = m_product->sampleLeaf(u, leafProbability);
        SquareSample s = m_fine->sampleWithin(leaf, u);
        s.pdf *= leafProbability;
        return s;
    }

    double pdf(glm::dvec2 point) const {
        double leafProbability = 0.0;
        const SquareCell leaf = m_product->leafAt(point, leafProbability);
        if (leafProbability == 0.0)
            return 0.0;
        return leafProbability * m_fine->pdfWithin(leaf, point);
    }

    // The u that sample(u) maps to `point` (the fine warp inside the leaf, then the product's).
    glm::dvec2 invert(glm::dvec2 point) const {
        double leafProbability = 0.0;
        const SquareCell leaf = m_product->leafAt(point, leafProbability);
        return m_product->invertAbove(point, m_fine->invertWithin(leaf, point));
    }

private:
    const HierarchicalSampler* m_product;
    const HierarchicalSampler* m_fine;
};

} // namespace wavelit::wavelet
