// The status line's noise estimate (panels/noise_estimate.h) against a closed form: images whose
// pixels are means of Gaussian samples of known variance s^2 (different per pixel). The estimator
// must recover the mean of s^2 and report sqrt(mean s^2 / n) / mean at n spp, within the
// statistical error of the estimate itself (4096 pixels: ~3 % standard error; bounds ~3 sigma).
#include "panels/noise_estimate.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace wavelit;
using namespace wavelit::editor;

class PanelsNoiseEstimateTest : public QObject {
    Q_OBJECT
private slots:
    void recoversKnownVariance();
    void restartsOnNewGeneration();
};

namespace {

// Per pixel: `total` samples of N(mu, s^2) (grey, so luminance = value); returns the means after
// `first` and after `total` samples.
std::pair<util::ImageRGB, util::ImageRGB> sampleImages(int first, int total, double* meanVariance) {
    constexpr int kSide = 64;
    std::mt19937 rng(7);
    util::ImageRGB a(kSide, kSide), m(kSide, kSide);
    double sumVariance = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const double mu = 0.5 + 0.4 * std::sin(double(i)), s = 0.05 + 0.3 * double(i % 7) / 7.0;
        sumVariance += s * s;
        std::normal_distribution<double> sample(mu, s);
        double sum = 0.0, sumFirst = 0.0;
        for (int k = 0; k < total; ++k) {
            sum += sample(rng);
            if (k + 1 == first) sumFirst = sum;
        }
        a.pixels[i] = glm::vec3(float(sumFirst / first));
        m.pixels[i] = glm::vec3(float(sum / total));
    }
    *meanVariance = sumVariance / double(a.pixels.size());
    return {a, m};
}

} // namespace

void PanelsNoiseEstimateTest::recoversKnownVariance() {
    double variance = 0.0;
    auto [a, m] = sampleImages(4, 16, &variance);
    const auto fit = NoiseEstimator::fit(a, 4, m, 16);
    QVERIFY(fit);
    qInfo("per-sample variance: estimated %.5f, true %.5f", fit->sampleVariance, variance);
    QVERIFY(std::abs(fit->sampleVariance / variance - 1.0) < 0.1);

    NoiseEstimator estimator;
    estimator.add(std::make_shared<const util::ImageRGB>(a), 4, 1);
    QVERIFY(!estimator.relativeNoise(4)); // one frame: no estimate yet
    estimator.add(std::make_shared<const util::ImageRGB>(m), 16, 1);
    const auto noise = estimator.relativeNoise(16);
    QVERIFY(noise);
    const double expected = std::sqrt(variance / 16.0) / fit->meanLuminance;
    qInfo("relative noise at 16 spp: %.5f, from the true variance %.5f", *noise, expected);
    QVERIFY(std::abs(*noise / expected - 1.0) < 0.05);
    // Four times the samples: half the noise.
    QVERIFY(std::abs(*estimator.relativeNoise(64) / *noise - 0.5) < 1e-9);
}

void PanelsNoiseEstimateTest::restartsOnNewGeneration() {
    double variance = 0.0;
    auto [a, m] = sampleImages(2, 8, &variance);
    NoiseEstimator estimator;
    estimator.add(std::make_shared<const util::ImageRGB>(a), 2, 1);
    estimator.add(std::make_shared<const util::ImageRGB>(m), 8, 2); // an edit came in between
    QVERIFY(!estimator.relativeNoise(8));
}

QTEST_MAIN(PanelsNoiseEstimateTest)
#include "panels_noise_estimate_test.moc"
