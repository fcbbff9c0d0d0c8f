// EXR (OpenEXR) and Radiance .hdr images through scene::loadImage with its default options (what
// every scene load uses): bytes -> input<WAVELIT_FUZZ_EXT> -> loadImage. An error must name the
// file; a loaded image must be what image_io.h promises: its size within the limit, one texel per
// pixel, every texel finite and non-negative after sanitising.
#include "fuzz_support.h"

#include "scene/image_io.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace wavelit;
    const std::string path = fuzz::writeInput(data, size, std::string("input") + WAVELIT_FUZZ_EXT);
    const scene::ImageLoadOptions options;
    auto loaded = scene::loadImage(path, options);
    if (!loaded) {
        fuzz::checkError(loaded.error(), path);
        return 0;
    }
    const util::ImageRGB& image = loaded->image;
    if (image.width <= 0 || image.height <= 0 || image.width > options.maxDimension || image.height > options.maxDimension)
        fuzz::finding("loaded a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " image");
    if (image.pixels.size() != size_t(image.width) * size_t(image.height)) fuzz::finding("texel count != width x height");
    for (const glm::vec3& p : image.pixels)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(p[c]) || p[c] < 0.0f) fuzz::finding("a texel is " + std::to_string(p[c]) + " after sanitising");
    return 0;
}
