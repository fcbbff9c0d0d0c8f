#include "render/testing/pixel_moments.h"

#include "util/image.h"

#include <algorithm>
#include <cmath>

namespace wavelit::render {

PixelMoments pixelMoments(const CpuPathTracer& tracer, int width, int height, int passes,
                          MomentChannel channel) {
    double sum = 0.0, varianceSum = 0.0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double s1 = 0.0, s2 = 0.0;
            for (int pass = 0; pass < passes; ++pass) {
                const glm::vec3 rgb = tracer.samplePixel(x, y, pass);
                const double v = channel == MomentChannel::Red ? rgb.x : util::luminance(rgb);
                s1 += v;
                s2 += v * v;
            }
            const double mean = s1 / passes;
            sum += mean;
            varianceSum += std::max(0.0, s2 - passes * mean * mean) / (passes - 1);
        }
    const double pixels = double(width) * height;
    PixelMoments m;
    m.mean = sum / pixels;
    m.pixelVariance = varianceSum / pixels;
    m.standardError = std::sqrt(varianceSum / passes) / pixels;
    return m;
}

} // namespace wavelit::render
