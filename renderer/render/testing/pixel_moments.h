// The image mean of a CPU tracer's per-sample values and its standard error, for tests that
// compare two estimators' means (strategies, samplers, roulette on/off). The error comes from
// each pixel's own sample variance: the image's spatial variation is not noise, since every
// estimator sees the same pixels.
#pragma once

#include "render/reference/cpu_path_tracer.h"

namespace wavelit::render {

struct PixelMoments {
    double mean = 0.0;          // over pixels of each pixel's mean over the passes
    double standardError = 0.0; // of `mean`
    double pixelVariance = 0.0; // one sample's variance, averaged over pixels
};

// Which number of a sample's RGB the moments are of.
enum class MomentChannel { Red, Luminance };

// Samples passes 0 .. passes-1 of every pixel of a width × height image (passes >= 2).
PixelMoments pixelMoments(const CpuPathTracer& tracer, int width, int height, int passes,
                          MomentChannel channel = MomentChannel::Red);

} // namespace wavelit::render
