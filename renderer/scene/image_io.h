// Reading and writing images: OpenEXR (scanline/tiled, half/float, RGB/RGBA/Y) and a small
// Radiance .hdr reader; 8-bit sRGB PNG for display output. Every failure names the file.
#pragma once

#include "util/image.h"
#include "util/result.h"

#include <string>
#include <vector>

namespace wavelit::scene {

struct ImageLoadOptions {
    // NaN/Inf texels are replaced by 0 and negative ones clamped to 0 with a warning when true;
    // when false they are an error naming the first bad texel.
    bool sanitize = true;
    int maxDimension = 16384; // larger images are rejected (memory safety on corrupt headers)
};

struct LoadedImage {
    util::ImageRGB image;
    std::vector<std::string> warnings; // e.g. "city.exr: 3 NaN texels replaced by 0"
};

util::Result<LoadedImage> loadImage(const std::string& path, const ImageLoadOptions& options = {});

// Writes linear float RGB as EXR (FLOAT channels R,G,B, ZIP compression). Atomic: temp + rename.
util::Status writeExr(const std::string& path, const util::ImageRGB& image);

// Writes 8-bit sRGB PNG after multiplying by 2^exposureEv and clamping (display transform).
util::Status writePng(const std::string& path, const util::ImageRGB& image, float exposureEv = 0.0f);

// Chooses EXR or PNG by extension (.exr / .png); anything else is a Usage error.
util::Status writeImage(const std::string& path, const util::ImageRGB& image, float exposureEv = 0.0f);

} // namespace wavelit::scene
