#include "scene/exr_layers.h"

#include "scene/atomic_file.h"
#include "scene/load_guard.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

namespace {

constexpr const char* kChannels[3] = {"R", "G", "B"};

std::string channelName(const std::string& layer, int c) {
    return layer.empty() ? std::string(kChannels[c]) : layer + "." + kChannels[c];
}

// Slices of one RGB image (float RGB per pixel, rows of `width`) under the layer's channel names.
void insertSlices(Imf::FrameBuffer& fb, const std::string& layer, util::ImageRGB& image) {
    char* base = reinterpret_cast<char*>(image.pixels.data());
    const size_t xs = sizeof(glm::vec3), ys = xs * size_t(image.width);
    for (int c = 0; c < 3; ++c)
        fb.insert(channelName(layer, c), Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys,
                                                    1, 1, 0.0));
}

util::Status checkLayers(const std::string& path, const LayeredImage& image) {
    if (image.beauty.empty()) return makeError(ErrorKind::Invalid, path, "cannot write an empty image");
    std::set<std::string> seen;
    for (const ExrLayerImage& layer : image.layers) {
        if (layer.name.empty() || layer.name.find('.') != std::string::npos ||
            layer.name == "R" || layer.name == "G" || layer.name == "B")
            return makeError(ErrorKind::Invalid, path,
                             "layer name '" + layer.name + "' is empty, contains '.' or is R, G or B");
        if (!seen.insert(layer.name).second)
            return makeError(ErrorKind::Invalid, path, "layer '" + layer.name + "' appears twice");
        if (layer.image.width != image.beauty.width || layer.image.height != image.beauty.height)
            return makeError(ErrorKind::Invalid, path,
                             "layer '" + layer.name + "' is not the beauty's size");
    }
    return util::okStatus();
}

} // namespace

util::Status writeExrLayers(const std::string& path, const LayeredImage& image) {
    if (auto ok = checkLayers(path, image); !ok) return ok;
    try {
        Imf::StdOSStream stream;
        Imf::Header header(image.beauty.width, image.beauty.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (int c = 0; c < 3; ++c) header.channels().insert(kChannels[c], Imf::Channel(Imf::FLOAT));
        for (const ExrLayerImage& layer : image.layers)
            for (int c = 0; c < 3; ++c)
                header.channels().insert(channelName(layer.name, c), Imf::Channel(Imf::FLOAT));
        for (const auto& [name, text] : image.attributes)
            header.insert(name, Imf::StringAttribute(text));
        // OpenEXR's slices take non-const pointers: write from copies.
        LayeredImage copy = image;
        {
            Imf::OutputFile file(stream, header);
            Imf::FrameBuffer fb;
            insertSlices(fb, "", copy.beauty);
            for (ExrLayerImage& layer : copy.layers) insertSlices(fb, layer.name, layer.image);
            file.setFrameBuffer(fb);
            file.writePixels(image.beauty.height);
        }
        return writeFileAtomic(path, stream.str());
    } catch (const std::exception& e) {
        return makeError(ErrorKind::Io, path, std::string("cannot encode EXR: ") + e.what());
    }
}

util::Result<LayeredImage> readExrLayers(const std::string& path, int maxDimension) {
    return guardLoad<LayeredImage>(path, [&]() -> util::Result<LayeredImage> {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec))
            return makeError(ErrorKind::NotFound, path, "no such image file");
        try {
            Imf::InputFile file(path.c_str());
            const Imath::Box2i dw = file.header().dataWindow();
            const long long w = (long long)dw.max.x - dw.min.x + 1;
            const long long h = (long long)dw.max.y - dw.min.y + 1;
            if (w <= 0 || h <= 0) return makeError(ErrorKind::Format, path, "empty data window");
            if (w > maxDimension || h > maxDimension)
                return makeError(ErrorKind::Invalid, path,
                                 std::to_string(w) + "x" + std::to_string(h) + " exceeds the " +
                                     std::to_string(maxDimension) + " pixel limit per side");
            // Channels by layer: "" for R, G, B; "sun" for sun.R, sun.G, sun.B.
            std::map<std::string, std::set<std::string>> layers;
            const Imf::ChannelList& channels = file.header().channels();
            for (auto i = channels.begin(); i != channels.end(); ++i) {
                const std::string name = i.name();
                const size_t dot = name.rfind('.');
                const std::string layer = dot == std::string::npos ? "" : name.substr(0, dot);
                layers[layer].insert(dot == std::string::npos ? name : name.substr(dot + 1));
            }
            auto complete = [](const std::set<std::string>& c) {
                return c.count("R") && c.count("G") && c.count("B");
            };
            if (!complete(layers[""]))
                return makeError(ErrorKind::Unsupported, path, "no R,G,B channels (the beauty)");
            LayeredImage out;
            for (const auto& [name, parts] : layers) {
                if (name.empty()) continue;
                const bool any = parts.count("R") || parts.count("G") || parts.count("B");
                if (!any) continue; // another kind of channel (alpha, depth...): not a light group
                if (!complete(parts))
                    return makeError(ErrorKind::Format, path,
                                     "layer '" + name + "' lacks one of " + name + ".R, " + name +
                                         ".G, " + name + ".B");
                out.layers.push_back({name, util::ImageRGB()});
            }
            // A header can claim any size: refuse what could not be a render before allocating.
            constexpr uint64_t kMaxBytes = uint64_t(8) << 30;
            const uint64_t bytes =
                uint64_t(w) * uint64_t(h) * (out.layers.size() + 1) * sizeof(glm::vec3);
            if (bytes > kMaxBytes)
                return makeError(ErrorKind::Invalid, path,
                                 std::to_string(w) + "x" + std::to_string(h) + " with " +
                                     std::to_string(out.layers.size()) +
                                     " layers needs more than 8 GiB");
            out.beauty = util::ImageRGB(int(w), int(h));
            for (ExrLayerImage& layer : out.layers) layer.image = util::ImageRGB(int(w), int(h));
            Imf::FrameBuffer fb;
            // Slices address data-window coordinates: shift the bases so (min.x, min.y) is pixel 0.
            const ptrdiff_t shift = (ptrdiff_t(dw.min.x) + ptrdiff_t(dw.min.y) * ptrdiff_t(w)) *
                                    ptrdiff_t(sizeof(glm::vec3));
            auto insert = [&](const std::string& layer, util::ImageRGB& image) {
                char* base = reinterpret_cast<char*>(image.pixels.data()) - shift;
                const size_t xs = sizeof(glm::vec3), ys = xs * size_t(w);
                for (int c = 0; c < 3; ++c)
                    fb.insert(channelName(layer, c),
                              Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys, 1, 1, 0.0));
            };
            insert("", out.beauty);
            for (ExrLayerImage& layer : out.layers) insert(layer.name, layer.image);
            file.setFrameBuffer(fb);
            file.readPixels(dw.min.y, dw.max.y);
            for (auto i = file.header().begin(); i != file.header().end(); ++i)
                if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&i.attribute()))
                    out.attributes[i.name()] = text->value();
            return out;
        } catch (const std::exception& e) {
            return makeError(ErrorKind::Format, path, std::string("cannot read EXR: ") + e.what());
        }
    });
}

} // namespace wavelit::scene
