// A progressive render's per-pass block means (BlockStatistics), and the block-by-block test that
// two renders have the same mean, for the image tests of the product caches: each pass's own image
// is recovered from the running means before and after it (one sample per pixel), and its
// luminance-free channel sum averaged over block x block squares. Header-only; tests.
#pragma once

#include "render/session/integrator.h"
#include "render/testing/block_statistics.h"

#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

namespace wavelit::render {

// `passes` passes of `tracer`, whose image is size x size pixels, in blocks of block x block.
inline BlockStatistics passBlockStatistics(Integrator& tracer, int passes, int size, int block) {
    const int perRow = size / block;
    BlockStatistics stats(size_t(perRow * perRow));
    std::vector<glm::dvec3> previous(size_t(size * size), glm::dvec3(0.0));
    for (int pass = 1; pass <= passes; ++pass) {
        EXPECT_TRUE(tracer.renderPass().ok());
        auto img = tracer.image();
        EXPECT_TRUE(img.ok());
        std::vector<double> blocks(stats.blocks(), 0.0);
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const size_t i = size_t(y * size + x);
                const glm::dvec3 mean(img->pixels[i]);
                const glm::dvec3 sample = mean * double(pass) - previous[i] * double(pass - 1);
                previous[i] = mean;
                blocks[size_t((y / block) * perRow + x / block)] +=
                    (sample.r + sample.g + sample.b) / double(block * block);
            }
        stats.addPass(blocks);
    }
    return stats;
}

// Every block within 4 sigma (asserted); how many within 3 is printed for the log.
inline void expectSameBlockMeans(const BlockStatistics& a, const BlockStatistics& b,
                                 const char* what) {
    int within3 = 0;
    for (size_t i = 0; i < a.blocks(); ++i) {
        const double z = (a.mean(i) - b.mean(i)) / combinedSigma(a, b, i);
        EXPECT_LT(std::abs(z), 4.0) << what << ": block " << i << " " << a.mean(i) << " vs "
                                    << b.mean(i);
        within3 += std::abs(z) < 3.0 ? 1 : 0;
    }
    std::printf("%s: %d of %zu blocks within 3 sigma\n", what, within3, a.blocks());
}

} // namespace wavelit::render
