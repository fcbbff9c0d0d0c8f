// Per-block statistics of a progressive render for the samplers' image tests: each pass gives one
// mean per block (one sample per pixel), and a block's estimate is the mean of those per-pass
// means, with the standard error taken from their spread. Comparing two renders block by block
// then needs only their means and the combined standard error (combinedSigma). Header-only; tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace wavelit::render {

class BlockStatistics {
public:
    explicit BlockStatistics(size_t blocks) : m_sum(blocks, 0.0), m_sum2(blocks, 0.0) {}

    void addPass(const std::vector<double>& blockMeans) {
        for (size_t i = 0; i < m_sum.size(); ++i) {
            m_sum[i] += blockMeans[i];
            m_sum2[i] += blockMeans[i] * blockMeans[i];
        }
        ++m_passes;
    }

    size_t blocks() const { return m_sum.size(); }
    double mean(size_t i) const { return m_passes > 0 ? m_sum[i] / m_passes : 0.0; }
    double standardError(size_t i) const {
        if (m_passes < 2)
            return 0.0;
        const double m = mean(i);
        const double var =
            std::max(0.0, m_sum2[i] / m_passes - m * m) * m_passes / (m_passes - 1);
        return std::sqrt(var / m_passes);
    }

private:
    std::vector<double> m_sum, m_sum2;
    int m_passes = 0;
};

// The standard error of a - b for block i of two independent renders.
inline double combinedSigma(const BlockStatistics& a, const BlockStatistics& b, size_t i) {
    return std::sqrt(a.standardError(i) * a.standardError(i) +
                     b.standardError(i) * b.standardError(i));
}

} // namespace wavelit::render
