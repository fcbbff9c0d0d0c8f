#include "render/session/image_metrics.h"

#include "util/check.h"

#include <cmath>

namespace wavelit::render {

double rmse(const util::ImageRGB& image, const util::ImageRGB& reference) {
    WAVELIT_CHECK(image.width == reference.width && image.height == reference.height);
    double sum = 0.0;
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double d = double(image.pixels[i][c]) - double(reference.pixels[i][c]);
            sum += d * d;
        }
    return image.pixels.empty() ? 0.0 : std::sqrt(sum / (3.0 * double(image.pixels.size())));
}

double relativeMse(const util::ImageRGB& image, const util::ImageRGB& reference) {
    WAVELIT_CHECK(image.width == reference.width && image.height == reference.height);
    constexpr double kDarkPixelEpsilon = 1e-2; // keeps near-black reference pixels from dominating
    double sum = 0.0;
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double r = reference.pixels[i][c];
            double d = double(image.pixels[i][c]) - r;
            sum += d * d / (r * r + kDarkPixelEpsilon);
        }
    return image.pixels.empty() ? 0.0 : sum / (3.0 * double(image.pixels.size()));
}

size_t countNonFinite(const util::ImageRGB& image) {
    size_t n = 0;
    for (const auto& p : image.pixels)
        for (int c = 0; c < 3; ++c) n += std::isfinite(p[c]) ? 0 : 1;
    return n;
}

double meanValue(const util::ImageRGB& image) {
    double sum = 0.0;
    for (const auto& p : image.pixels) sum += (double(p.r) + p.g + p.b) / 3.0;
    return image.pixels.empty() ? 0.0 : sum / double(image.pixels.size());
}

} // namespace wavelit::render
