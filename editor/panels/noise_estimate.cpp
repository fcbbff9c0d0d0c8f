#include "panels/noise_estimate.h"

#include <cmath>

namespace wavelit::editor {

std::optional<NoiseEstimator::Fit> NoiseEstimator::fit(const util::ImageRGB& a, int aSpp,
                                                       const util::ImageRGB& m, int mSpp) {
    if (a.width != m.width || a.height != m.height || a.empty() || aSpp <= 0 || mSpp <= aSpp)
        return std::nullopt;
    const double na = aSpp, nm = mSpp, nb = nm - na;
    double sumSquares = 0.0, sumLuminance = 0.0;
    for (size_t i = 0; i < m.pixels.size(); ++i) {
        const double la = util::luminance(a.pixels[i]);
        const double lm = util::luminance(m.pixels[i]);
        const double lb = (nm * lm - na * la) / nb; // the later samples alone
        sumSquares += (la - lb) * (la - lb);
        sumLuminance += lm;
    }
    const double pixels = double(m.pixels.size());
    Fit out;
    out.sampleVariance = sumSquares / pixels / (1.0 / na + 1.0 / nb);
    out.meanLuminance = sumLuminance / pixels;
    if (!std::isfinite(out.sampleVariance) || !std::isfinite(out.meanLuminance)) return std::nullopt;
    return out;
}

void NoiseEstimator::add(std::shared_ptr<const util::ImageRGB> image, int samplesPerPixel, uint64_t generation) {
    if (!image || samplesPerPixel <= 0) return;
    const bool restart = !m_kept || generation != m_generation || image->width != m_kept->width ||
                         image->height != m_kept->height || samplesPerPixel < m_keptSpp;
    if (restart) {
        m_fit.reset();
    } else if (samplesPerPixel < 2 * m_keptSpp) {
        return; // not yet twice the kept samples: the kept frame stays
    } else if (auto f = fit(*m_kept, m_keptSpp, *image, samplesPerPixel)) {
        m_fit = f;
    }
    m_kept = std::move(image);
    m_keptSpp = samplesPerPixel;
    m_generation = generation;
}

std::optional<double> NoiseEstimator::relativeNoise(int samplesPerPixel) const {
    if (!m_fit || samplesPerPixel <= 0 || m_fit->meanLuminance <= 0.0) return std::nullopt;
    return std::sqrt(m_fit->sampleVariance / samplesPerPixel) / m_fit->meanLuminance;
}

} // namespace wavelit::editor
