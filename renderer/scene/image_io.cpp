#include "scene/image_io.h"

#include "scene/atomic_file.h"
#include "scene/image_io_exr_check.h"
#include "scene/load_guard.h"
#include "scene/radiance_hdr.h"
#include "util/path_util.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfStdIO.h>
#include <Iex.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sstream>

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

namespace {

using util::lowerExtension;

util::Result<util::ImageRGB> readExr(const std::string& path, int maxDimension) {
    // OpenEXR allocates what a file states before reading it (image_io_exr_check.h).
    if (auto s = checkExrLayout(path, maxDimension); !s) return s.error();
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i dw = file.header().dataWindow();
        const long long w = (long long)dw.max.x - dw.min.x + 1;
        const long long h = (long long)dw.max.y - dw.min.y + 1;
        if (w <= 0 || h <= 0)
            return makeError(ErrorKind::Format, path, "empty data window");
        if (w > maxDimension || h > maxDimension)
            return makeError(ErrorKind::Invalid, path,
                             std::to_string(w) + "x" + std::to_string(h) + " exceeds the " +
                                 std::to_string(maxDimension) + " pixel limit per side");
        const Imf::ChannelList& channels = file.header().channels();
        const bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
        const bool grey = channels.findChannel("Y") != nullptr;
        if (!rgb && !grey)
            return makeError(ErrorKind::Unsupported, path, "no R,G,B or Y channels");

        // Read in bands of rows (at most 64, at most 2^16 pixels) and the last band first: a corrupt
        // header stating a huge data window over a few bytes fails there, before the image is
        // allocated (a 1 KB file could otherwise cost gigabytes), and a band stays small however
        // wide the image claims to be.
        const long long bandRows = std::clamp<long long>((1 << 16) / w, 1, 64);
        std::vector<glm::vec3> band;
        auto readBand = [&](long long y0, long long y1) {
            band.assign(size_t(w) * size_t(y1 - y0 + 1), glm::vec3(0.0f));
            // Slices address pixel (x, y) of the data window; OpenEXR wants the base pointer
            // shifted so that (dw.min.x, y0) lands on band[0].
            char* base = reinterpret_cast<char*>(band.data()) -
                         (ptrdiff_t(dw.min.x) + ptrdiff_t(y0) * ptrdiff_t(w)) * ptrdiff_t(sizeof(glm::vec3));
            const size_t xs = sizeof(glm::vec3), ys = sizeof(glm::vec3) * size_t(w);
            Imf::FrameBuffer fb;
            if (rgb) {
                fb.insert("R", Imf::Slice(Imf::FLOAT, base + 0 * sizeof(float), xs, ys, 1, 1, 0.0));
                fb.insert("G", Imf::Slice(Imf::FLOAT, base + 1 * sizeof(float), xs, ys, 1, 1, 0.0));
                fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xs, ys, 1, 1, 0.0));
            } else {
                fb.insert("Y", Imf::Slice(Imf::FLOAT, base, xs, ys, 1, 1, 0.0));
            }
            file.setFrameBuffer(fb);
            file.readPixels(int(y0), int(y1));
            if (!rgb)
                for (auto& p : band) p = glm::vec3(p.r);
        };
        readBand(std::max<long long>(dw.min.y, dw.max.y - bandRows + 1), dw.max.y);
        util::ImageRGB image;
        image.width = int(w);
        image.height = int(h);
        image.pixels.reserve(size_t(w) * size_t(h));
        for (long long y0 = dw.min.y; y0 <= dw.max.y; y0 += bandRows) {
            readBand(y0, std::min<long long>(y0 + bandRows - 1, dw.max.y));
            image.pixels.insert(image.pixels.end(), band.begin(), band.end());
        }
        return image;
    } catch (const std::exception& e) {
        return makeError(ErrorKind::Format, path, std::string("cannot read EXR: ") + e.what());
    }
}

// Replaces NaN/Inf/negative texels (or reports the first one). Radiance is non-negative and
// finite; a single NaN texel would otherwise poison every integral and sampling table built on it.
util::Status sanitize(LoadedImage& loaded, const std::string& path, bool fix) {
    size_t nonFinite = 0, negative = 0;
    for (size_t i = 0; i < loaded.image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            float& v = loaded.image.pixels[i][c];
            const bool bad = !std::isfinite(v);
            if (!bad && v >= 0.0f) continue;
            if (!fix) {
                int x = int(i % size_t(loaded.image.width)), y = int(i / size_t(loaded.image.width));
                return makeError(ErrorKind::Invalid, path,
                                 std::string(bad ? "non-finite" : "negative") + " texel value at (" +
                                     std::to_string(x) + ", " + std::to_string(y) + ")");
            }
            (bad ? nonFinite : negative)++;
            v = 0.0f;
        }
    }
    if (nonFinite)
        loaded.warnings.push_back(path + ": " + std::to_string(nonFinite) +
                                  " NaN/Inf texel values replaced by 0");
    if (negative)
        loaded.warnings.push_back(path + ": " + std::to_string(negative) +
                                  " negative texel values clamped to 0");
    return util::okStatus();
}

void appendBigEndian(std::string& out, uint32_t v) {
    out.push_back(char(v >> 24));
    out.push_back(char(v >> 16));
    out.push_back(char(v >> 8));
    out.push_back(char(v));
}

void appendChunk(std::string& out, const char* type, const std::string& data) {
    appendBigEndian(out, uint32_t(data.size()));
    std::string typed = std::string(type, 4) + data;
    out += typed;
    appendBigEndian(out, uint32_t(crc32(0, reinterpret_cast<const Bytef*>(typed.data()), uInt(typed.size()))));
}

float linearToSrgb(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

} // namespace

namespace {

util::Result<LoadedImage> loadImageUnguarded(const std::string& path, const ImageLoadOptions& options) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return makeError(ErrorKind::NotFound, path, "no such image file");
    const std::string ext = lowerExtension(path);
    util::Result<util::ImageRGB> image = util::ImageRGB{};
    if (ext == ".exr")
        image = readExr(path, options.maxDimension);
    else if (ext == ".hdr" || ext == ".pic")
        image = readRadianceHdr(path, options.maxDimension);
    else
        return makeError(ErrorKind::Unsupported, path, "unknown image type '" + ext + "' (use .exr or .hdr)");
    if (!image) return image.error();
    LoadedImage loaded{std::move(image).value(), {}};
    if (auto s = sanitize(loaded, path, options.sanitize); !s) return s.error();
    return loaded;
}

} // namespace

util::Result<LoadedImage> loadImage(const std::string& path, const ImageLoadOptions& options) {
    return guardLoad<LoadedImage>(path, [&] { return loadImageUnguarded(path, options); });
}

util::Status writeExr(const std::string& path, const util::ImageRGB& image,
                      const ExrAttributes& attributes) {
    if (image.empty()) return makeError(ErrorKind::Invalid, path, "cannot write an empty image");
    // Encode in memory, then replace the file atomically (scene/atomic_file.h): a failed write
    // never leaves a truncated image where a good one was.
    try {
        Imf::StdOSStream stream;
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        header.channels().insert("R", Imf::Channel(Imf::FLOAT));
        header.channels().insert("G", Imf::Channel(Imf::FLOAT));
        header.channels().insert("B", Imf::Channel(Imf::FLOAT));
        for (const auto& [name, text] : attributes)
            header.insert(name, Imf::StringAttribute(text));
        {
            Imf::OutputFile file(stream, header);
            char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
            const size_t xs = sizeof(glm::vec3), ys = xs * size_t(image.width);
            Imf::FrameBuffer fb;
            fb.insert("R", Imf::Slice(Imf::FLOAT, base + 0 * sizeof(float), xs, ys));
            fb.insert("G", Imf::Slice(Imf::FLOAT, base + 1 * sizeof(float), xs, ys));
            fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xs, ys));
            file.setFrameBuffer(fb);
            file.writePixels(image.height);
        }
        return writeFileAtomic(path, stream.str());
    } catch (const std::exception& e) {
        return makeError(ErrorKind::Io, path, std::string("cannot encode EXR: ") + e.what());
    }
}

util::Result<ExrAttributes> readExrAttributes(const std::string& path) {
    return guardLoad<ExrAttributes>(path, [&]() -> util::Result<ExrAttributes> {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec))
            return makeError(ErrorKind::NotFound, path, "no such image file");
        if (auto s = checkExrHeaders(path, ImageLoadOptions{}.maxDimension); !s) return s.error();
        try {
            Imf::InputFile file(path.c_str());
            ExrAttributes attributes;
            for (auto i = file.header().begin(); i != file.header().end(); ++i)
                if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&i.attribute()))
                    attributes[i.name()] = text->value();
            return attributes;
        } catch (const std::exception& e) {
            return makeError(ErrorKind::Format, path, std::string("cannot read EXR: ") + e.what());
        }
    });
}

util::Status writePng(const std::string& path, const util::ImageRGB& image, float exposureEv) {
    if (image.empty()) return makeError(ErrorKind::Invalid, path, "cannot write an empty image");
    const float scale = std::exp2(exposureEv);
    std::string raw;
    raw.reserve(size_t(image.height) * (size_t(image.width) * 3 + 1));
    for (int y = 0; y < image.height; ++y) {
        raw.push_back(0); // filter type: none
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                float v = image.at(x, y)[c] * scale;
                if (!std::isfinite(v)) v = 0.0f;
                raw.push_back(char(uint8_t(std::lround(linearToSrgb(v) * 255.0f))));
            }
    }
    uLongf compressedSize = compressBound(uLong(raw.size()));
    std::string compressed(compressedSize, '\0');
    if (compress2(reinterpret_cast<Bytef*>(compressed.data()), &compressedSize,
                  reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()), 6) != Z_OK)
        return makeError(ErrorKind::Io, path, "zlib compression failed");
    compressed.resize(compressedSize);

    std::string png("\x89PNG\r\n\x1a\n", 8), ihdr;
    appendBigEndian(ihdr, uint32_t(image.width));
    appendBigEndian(ihdr, uint32_t(image.height));
    ihdr += std::string("\x08\x02\x00\x00\x00", 5); // 8 bit, RGB, deflate, no filter, no interlace
    appendChunk(png, "IHDR", ihdr);
    appendChunk(png, "IDAT", compressed);
    appendChunk(png, "IEND", "");

    return writeFileAtomic(path, png);
}

util::Status writeImage(const std::string& path, const util::ImageRGB& image, float exposureEv,
                        const ExrAttributes& attributes) {
    const std::string ext = lowerExtension(path);
    if (ext == ".exr") return writeExr(path, image, attributes);
    if (ext == ".png") return writePng(path, image, exposureEv);
    return makeError(ErrorKind::Usage, path, "output must end in .exr or .png");
}

} // namespace wavelit::scene
