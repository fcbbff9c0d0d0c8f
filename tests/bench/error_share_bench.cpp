// Error concentration of a render against a reference (issue 20, docs/performance.md):
//   error_share_bench REFERENCE.exr IMAGE.exr [SPP] [--map CELLS]
// prints relRMSE = RMS(lum(image) - lum(reference)) / mean(lum(reference)), the share of the
// squared error held by the top 0.1% of pixels (at least one), and relRMSE^2 x SPP (the per-sample
// figure: constant in SPP for an unbiased estimator while the reference's own error is small),
// and the ratio of the image's mean luminance to the reference's. --map CELLS also prints, for a
// CELLS x CELLS grid over the image, each cell's share of the squared error (percent) and its mean
// reference luminance: where in the picture the error lives.
#include "scene/image_io.h"
#include "util/image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace {

// Two rows per grid row: error share in percent, then the reference's mean luminance.
void printErrorMap(const wavelit::util::ImageRGB& ref, const std::vector<double>& sq, double total,
                   int cells) {
    std::vector<double> err(size_t(cells * cells), 0.0), lum(size_t(cells * cells), 0.0);
    std::vector<int> count(size_t(cells * cells), 0);
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const size_t c = size_t((y * cells / ref.height) * cells + x * cells / ref.width);
            const size_t i = size_t(y) * size_t(ref.width) + size_t(x);
            err[c] += sq[i];
            lum[c] += wavelit::util::luminance(ref.pixels[i]);
            ++count[c];
        }
    for (int cy = 0; cy < cells; ++cy) {
        std::printf("err%%");
        for (int cx = 0; cx < cells; ++cx)
            std::printf(" %6.2f", total > 0 ? 100.0 * err[size_t(cy * cells + cx)] / total : 0.0);
        std::printf("\nlum ");
        for (int cx = 0; cx < cells; ++cx) {
            const size_t c = size_t(cy * cells + cx);
            std::printf(" %6.3g", count[c] ? lum[c] / count[c] : 0.0);
        }
        std::printf("\n");
    }
}

}  // namespace

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
    int cells = 0;
    for (int a = 3; a + 1 < argc; ++a)
        if (std::string(argv[a]) == "--map") cells = std::atoi(argv[a + 1]);
    double mean = 0.0, total = 0.0, imageMean = 0.0;
    for (size_t i = 0; i < n; ++i) {
        imageMean += util::luminance(m.pixels[i]);
        const double e = double(util::luminance(m.pixels[i])) - double(util::luminance(r.pixels[i]));
        sq[i] = e * e;
        total += sq[i];
        mean += util::luminance(r.pixels[i]);
    }
    mean /= double(n);
    if (cells > 0) printErrorMap(r, sq, total, cells);
    std::sort(sq.begin(), sq.end(), std::greater<double>());
    const size_t top = std::max<size_t>(1, n / 1000);
    double topSum = 0.0;
    for (size_t i = 0; i < top; ++i) topSum += sq[i];
    const double relRmse = std::sqrt(total / double(n)) / mean;
    const double spp = argc > 3 && std::string(argv[3]) != "--map" ? std::atof(argv[3]) : 0.0;
    imageMean /= double(n);
    std::printf("relRMSE %.4g top0.1%%share %.3f relRMSE2xspp %.4g mean/ref %.4f (pixels %zu, "
                "top %zu)\n",
                relRmse, total > 0 ? topSum / total : 0.0, relRmse * relRmse * spp,
                imageMean / mean, n, top);
    return 0;
}
