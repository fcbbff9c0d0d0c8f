// Reading and writing images: OpenEXR (scanline/tiled, half/float, RGB/RGBA/Y) and a small
// Radiance .hdr reader; 8-bit sRGB PNG for display output. Every failure names the file.
#pragma once

#include "util/image.h"
#include "util/result.h"

#include <map>
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

// String attributes of an EXR header beyond the required ones, name -> text (a render's
// "wavelit:*" attributes: docs/file-formats.md "Rendered EXR").
using ExrAttributes = std::map<std::string, std::string>;

// Writes linear float RGB as EXR (FLOAT channels R,G,B, ZIP compression) with `attributes` as
// string attributes of its header. Atomic: temp + rename.
util::Status writeExr(const std::string& path, const util::ImageRGB& image,
                      const ExrAttributes& attributes = {});

// The string attributes of an EXR's header (attributes of other types are left out), without
// reading its pixels. Errors name the file.
util::Result<ExrAttributes> readExrAttributes(const std::string& path);

// Writes 8-bit sRGB PNG after multiplying by 2^exposureEv and clamping (display transform).
util::Status writePng(const std::string& path, const util::ImageRGB& image, float exposureEv = 0.0f);

// Chooses EXR or PNG by extension (.exr / .png); anything else is a Usage error. `attributes`
// go into an EXR's header; a PNG has none.
util::Status writeImage(const std::string& path, const util::ImageRGB& image, float exposureEv = 0.0f,
                        const ExrAttributes& attributes = {});

} // namespace wavelit::scene
