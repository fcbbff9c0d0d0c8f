// Defensive mixtures (architecture.md §4, pitfalls): the wavelet sampler approximates the integrand, so
// where the approximation is zero and the integrand is not, an estimator dividing by the wavelet
// pdf alone would be biased. Mixing in a distribution with full support (uniform over the square,
// or the caller's BSDF sampler through mixturePdf) keeps every direction reachable, and the
// estimator divides by the exact mixture pdf. Unit-square measure throughout.
#pragma once

#include "wavelet/hierarchical_sampler.h"

#include <algorithm>

namespace wavelit::wavelet {

// Exact pdf of "technique A with probability alpha, else technique B".
inline double mixturePdf(double alpha, double pdfA, double pdfB) {
    return alpha * pdfA + (1.0 - alpha) * pdfB;
}

// Any sampler with sample(dvec2) -> SquareSample and pdf(dvec2), mixed with the uniform
// distribution on the unit square. One uniform number selects the technique and is rescaled,
// so the result still consumes exactly two numbers.
template <typename Sampler> class UniformMixture {
public:
    UniformMixture(const Sampler& sampler, double alpha) : m_sampler(&sampler), m_alpha(alpha) {}

    SquareSample sample(glm::dvec2 u) const {
        SquareSample s;
        if (u.x < m_alpha) {
            u.x = std::min(u.x / m_alpha, 0x1.fffffffffffffp-1);
            s.point = m_sampler->sample(u).point;
        } else {
            u.x = std::min((u.x - m_alpha) / (1.0 - m_alpha), 0x1.fffffffffffffp-1);
            s.point = u;
        }
        // The pdf of a point is the mixture of both densities there, whichever technique drew it.
        s.pdf = pdf(s.point);
        return s;
    }

    double pdf(glm::dvec2 p) const {
        const bool inside = p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0;
        return mixturePdf(m_alpha, m_sampler->pdf(p), inside ? 1.0 : 0.0);
    }

private:
    const Sampler* m_sampler;
    double m_alpha;
};

} // namespace wavelit::wavelet
