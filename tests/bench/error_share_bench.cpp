// Error concentration of a render against a reference (issue 20, docs/performance.md):
//   error_share_bench REFERENCE.exr IMAGE.exr [SPP]
// prints relRMSE = RMS(lum(image) - lum(reference)) / mean(lum(reference)), the share of the
// squared error held by the top 0.1% of pixels (at least one), and relRMSE^2 x SPP (the per-sample
// figure: constant in SPP for an unbiased estimator while the reference's own error is small),
// and the ratio of the image's mean luminance to the reference's.
#include "scene/image_io.h"
#include "util/image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

int main(int argc, char** argv) {
    using namespace wavelit;
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s REFERENCE.exr IMAGE.exr [SPP]\n", argv[0]);
        return 2;
    }
    auto ref = scene::loadImage(argv[1]);
    auto img = scene::loadImage(argv[2]);
    if (!ref || !img) {
        std::fprintf(stderr, "cannot read %s\n", !ref ? argv[1] : argv[2]);
        return 1;
    }
    const util::ImageRGB& r = ref->image;
    const util::ImageRGB& m = img->image;
    if (r.width != m.width || r.height != m.height) {
        std::fprintf(stderr, "sizes differ\n");
        return 1;
    }
    const size_t n = r.pixels.size();
    std::vector<double> sq(n);
    double mean = 0.0, total = 0.0, imageMean = 0.0;
    for (size_t i = 0; i < n; ++i) {
        imageMean += util::luminance(m.pixels[i]);
        const double e = double(util::luminance(m.pixels[i])) - double(util::luminance(r.pixels[i]));
        sq[i] = e * e;
        total += sq[i];
        mean += util::luminance(r.pixels[i]);
    }
    mean /= double(n);
    std::sort(sq.begin(), sq.end(), std::greater<double>());
    const size_t top = std::max<size_t>(1, n / 1000);
    double topSum = 0.0;
    for (size_t i = 0; i < top; ++i) topSum += sq[i];
    const double relRmse = std::sqrt(total / double(n)) / mean;
    const double spp = argc > 3 ? std::atof(argv[3]) : 0.0;
    imageMean /= double(n);
    std::printf("relRMSE %.4g top0.1%%share %.3f relRMSE2xspp %.4g mean/ref %.4f (pixels %zu, "
                "top %zu)\n",
                relRmse, total > 0 ? topSum / total : 0.0, relRmse * relRmse * spp,
                imageMean / mean, n, top);
    return 0;
}
