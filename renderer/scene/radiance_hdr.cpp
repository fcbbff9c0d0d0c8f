#include "scene/radiance_hdr.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

namespace {

glm::vec3 rgbeToFloat(const uint8_t* rgbe) {
    if (rgbe[3] == 0) return glm::vec3(0.0f);
    const float f = std::ldexp(1.0f, int(rgbe[3]) - (128 + 8));
    return glm::vec3(rgbe[0] * f, rgbe[1] * f, rgbe[2] * f);
}

// One scanline of `width` RGBE pixels; new-style RLE stores each component separately.
bool readScanline(std::istream& in, int width, std::vector<uint8_t>& line) {
    uint8_t head[4];
    if (!in.read(reinterpret_cast<char*>(head), 4)) return false;
    const bool rle = width >= 8 && width < 32768 && head[0] == 2 && head[1] == 2 && !(head[2] & 0x80);
    if (!rle) { // flat scanline: the four bytes read are the first pixel
        std::copy(head, head + 4, line.begin());
        return bool(in.read(reinterpret_cast<char*>(line.data() + 4), std::streamsize(width - 1) * 4));
    }
    if (((int(head[2]) << 8) | head[3]) != width) return false;
    for (int c = 0; c < 4; ++c) {
        int x = 0;
        while (x < width) {
            int count = in.get();
            if (count == EOF) return false;
            if (count > 128) {
                count -= 128;
                int value = in.get();
                if (value == EOF || x + count > width) return false;
                for (int i = 0; i < count; ++i) line[size_t(x++) * 4 + c] = uint8_t(value);
            } else {
                if (count == 0 || x + count > width) return false;
                for (int i = 0; i < count; ++i) {
                    int value = in.get();
                    if (value == EOF) return false;
                    line[size_t(x++) * 4 + c] = uint8_t(value);
                }
            }
        }
    }
    return true;
}

} // namespace

util::Result<util::ImageRGB> readRadianceHdr(const std::string& path, int maxDimension) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return makeError(ErrorKind::Io, path, "cannot open");
    std::string line;
    if (!std::getline(in, line) || line.rfind("#?", 0) != 0)
        return makeError(ErrorKind::Format, path, "not a Radiance HDR file (missing #? header)");
    bool rgbe = false;
    while (std::getline(in, line) && !line.empty())
        if (line == "FORMAT=32-bit_rle_rgbe") rgbe = true;
    if (!rgbe) return makeError(ErrorKind::Unsupported, path, "only 32-bit_rle_rgbe is supported");
    if (!std::getline(in, line)) return makeError(ErrorKind::Format, path, "missing resolution line");
    int w = 0, h = 0;
    if (std::sscanf(line.c_str(), "-Y %d +X %d", &h, &w) != 2)
        return makeError(ErrorKind::Unsupported, path, "unsupported orientation '" + line + "'");
    if (w <= 0 || h <= 0 || w > maxDimension || h > maxDimension)
        return makeError(ErrorKind::Invalid, path, "bad size " + std::to_string(w) + "x" + std::to_string(h));
    // The smallest encoding of a scanline (RLE: 4 header bytes and, per component, one 2-byte
    // run per 127 pixels; flat: 4 bytes a pixel) bounds what the rest of the file can hold, so a
    // header claiming more rows than the bytes that follow is refused before the image is allocated
    // (a 46-byte file stating 16384x16384 made every load allocate 3 GiB).
    const std::streampos pixelsAt = in.tellg();
    in.seekg(0, std::ios::end);
    const uint64_t remaining = uint64_t(in.tellg() - pixelsAt);
    in.seekg(pixelsAt);
    const bool rlePossible = w >= 8 && w < 32768;
    const uint64_t minScanline = rlePossible ? 4 + 4 * 2 * ((uint64_t(w) + 126) / 127) : 4 * uint64_t(w);
    if (remaining < uint64_t(h) * minScanline)
        return makeError(ErrorKind::Format, path,
                         "truncated or corrupt scanlines: " + std::to_string(w) + "x" + std::to_string(h) +
                             " needs at least " + std::to_string(uint64_t(h) * minScanline) +
                             " bytes of pixel data, the file has " + std::to_string(remaining));
    util::ImageRGB image(w, h);
    std::vector<uint8_t> scan(size_t(w) * 4);
    for (int y = 0; y < h; ++y) {
        if (!readScanline(in, w, scan))
            return makeError(ErrorKind::Format, path, "truncated or corrupt scanline", "row " + std::to_string(y));
        for (int x = 0; x < w; ++x) image.at(x, y) = rgbeToFloat(&scan[size_t(x) * 4]);
    }
    return image;
}

} // namespace wavelit::scene
