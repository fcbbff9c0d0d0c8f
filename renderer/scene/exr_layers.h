// Multi-layer EXR for LightMix (docs/lightmix.md, docs/file-formats.md "Light-group EXR"): the
// beauty as channels R, G, B and each light group's layer as <group>.R, <group>.G, <group>.B
// (FLOAT, ZIP), with string attributes in the header as writeExr writes them. Every failure
// names the file.
#pragma once

#include "scene/image_io.h"
#include "util/image.h"
#include "util/result.h"

#include <string>
#include <vector>

namespace wavelit::scene {

struct ExrLayerImage {
    std::string name;
    util::ImageRGB image;
};

struct LayeredImage {
    util::ImageRGB beauty;
    std::vector<ExrLayerImage> layers; // as written; read back in the file's channel order (by name)
    ExrAttributes attributes;          // string attributes of the header
};

// Every layer must have the beauty's size and a non-empty name without '.' (the channel
// separator); names must be distinct and not R, G or B. Atomic: temp + rename.
util::Status writeExrLayers(const std::string& path, const LayeredImage& image);

// Reads R, G, B and every complete <name>.R/.G/.B triple. Errors: not an EXR, no R,G,B channels,
// a layer missing one of its three channels (named), a side over maxDimension.
util::Result<LayeredImage> readExrLayers(const std::string& path, int maxDimension = 16384);

} // namespace wavelit::scene
