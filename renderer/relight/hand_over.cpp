#include "relight/hand_over.h"

#include <algorithm>
#include <cmath>

namespace wavelit::relight {
namespace {
constexpr double kEpsilon = 1e-2; // render/session/image_metrics.h's relativeMse
}

HandOverEstimate estimateHandOver(const util::ImageRGB& preview, const util::ImageRGB& tracerMean,
                                  const util::ImageRGB& meanVariance) {
    HandOverEstimate out;
    const int w = tracerMean.width, h = tracerMean.height;
    if (w <= 0 || h <= 0 || preview.width <= 0 || preview.height <= 0 || meanVariance.width != w ||
        meanVariance.height != h)
        return out;
    double difference = 0.0, noise = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int px = std::min(preview.width - 1, int(int64_t(x) * preview.width / w));
            const int py = std::min(preview.height - 1, int(int64_t(y) * preview.height / h));
            const glm::vec3& p = preview.at(px, py);
            const glm::vec3& m = tracerMean.at(x, y);
            const glm::vec3& v = meanVariance.at(x, y);
            for (int c = 0; c < 3; ++c) {
                const double denom = double(p[c]) * double(p[c]) + kEpsilon;
                const double d = double(p[c]) - double(m[c]);
                difference += d * d / denom;
                noise += std::max(0.0, double(v[c])) / denom;
            }
        }
    const double n = 3.0 * double(w) * double(h);
    difference /= n;
    noise /= n;
    out.tracerRelRmse = std::sqrt(noise);
    out.previewRelRmse = std::sqrt(std::max(0.0, difference - noise));
    out.tracerBetter = noise < difference - noise;
    return out;
}

util::ImageRGB varianceOfMean(const util::ImageRGB& halfA, const util::ImageRGB& halfB) {
    util::ImageRGB out(halfA.width, halfA.height);
    if (halfB.width != halfA.width || halfB.height != halfA.height) return util::ImageRGB();
    for (size_t i = 0; i < out.pixels.size(); ++i) {
        const glm::vec3 d = 0.5f * (halfA.pixels[i] - halfB.pixels[i]);
        out.pixels[i] = d * d;
    }
    return out;
}

} // namespace wavelit::relight
