// The hand-over estimate against known errors: a synthetic converged image G, a preview with a
// known relative error against it, and a tracer whose two half-sample means are G plus Gaussian
// noise of a known variance. The estimates (made without G) match the true relative RMSEs
// (computed against G) within 10%, and the decision flips where the true errors cross.
#include "relight/hand_over.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace wavelit::relight {
namespace {

double relRmse(const util::ImageRGB& a, const util::ImageRGB& ref) {
    double sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.pixels[i][c]) - double(ref.pixels[i][c]);
            sum += d * d / (double(ref.pixels[i][c]) * ref.pixels[i][c] + 1e-2);
        }
    return std::sqrt(sum / (3.0 * double(a.pixels.size())));
}

struct Synthetic {
    util::ImageRGB truth, preview, halfA, halfB, mean;
};

// Relative noise `noise` per half-sample mean (so the full mean's is noise / sqrt 2).
Synthetic make(double previewBias, double noise) {
    const int n = 128;
    Synthetic s{util::ImageRGB(n, n), util::ImageRGB(n, n), util::ImageRGB(n, n), util::ImageRGB(n, n),
                util::ImageRGB(n, n)};
    std::mt19937 rng(7);
    auto gauss = [&] { // Box-Muller, so the numbers do not depend on the library's distributions
        const double u1 = (double(rng()) + 1.0) / 4294967297.0, u2 = double(rng()) / 4294967296.0;
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.14159265358979 * u2);
    };
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const glm::vec3 g(0.2f + 2.0f * float(x) / n, 0.5f + float(y) / n, 1.0f);
            s.truth.at(x, y) = g;
            // A preview wrong by +-previewBias relative in a checker (a shadow edge, a blurred lobe).
            s.preview.at(x, y) = g * float(1.0 + (((x / 4 + y / 4) % 2) ? previewBias : -previewBias));
            for (int c = 0; c < 3; ++c) {
                s.halfA.at(x, y)[c] = g[c] * float(1.0 + noise * gauss());
                s.halfB.at(x, y)[c] = g[c] * float(1.0 + noise * gauss());
            }
            s.mean.at(x, y) = 0.5f * (s.halfA.at(x, y) + s.halfB.at(x, y));
        }
    return s;
}

TEST(RelightHandOver, EstimatesBothErrorsWithoutTheReference) {
    for (const auto& [bias, noise] : {std::pair{0.2, 0.6}, std::pair{0.2, 0.1}, std::pair{0.05, 0.3}}) {
        const Synthetic s = make(bias, noise);
        const HandOverEstimate e = estimateHandOver(s.preview, s.mean, varianceOfMean(s.halfA, s.halfB));
        const double truePreview = relRmse(s.preview, s.truth), trueTracer = relRmse(s.mean, s.truth);
        EXPECT_NEAR(e.previewRelRmse, truePreview, 0.1 * truePreview) << bias << " " << noise;
        EXPECT_NEAR(e.tracerRelRmse, trueTracer, 0.1 * trueTracer) << bias << " " << noise;
        EXPECT_EQ(e.tracerBetter, trueTracer < truePreview) << bias << " " << noise;
    }
}

TEST(RelightHandOver, MismatchedOrEmptyImagesKeepThePreview) {
    const util::ImageRGB a(4, 4, glm::vec3(1.0f)), b(5, 4, glm::vec3(1.0f));
    EXPECT_FALSE(estimateHandOver(a, a, b).tracerBetter);
    EXPECT_FALSE(estimateHandOver(util::ImageRGB(), a, a).tracerBetter);
    EXPECT_TRUE(varianceOfMean(a, b).pixels.empty());
}

} // namespace
} // namespace wavelit::relight
