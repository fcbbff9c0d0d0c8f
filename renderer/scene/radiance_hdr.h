// Reader for Radiance RGBE (.hdr) images: flat and new-style run-length encoded scanlines,
// "-Y H +X W" orientation only (what every current tool writes).
#pragma once

#include "util/image.h"
#include "util/result.h"

#include <string>

namespace wavelit::scene {

util::Result<util::ImageRGB> readRadianceHdr(const std::string& path, int maxDimension);

} // namespace wavelit::scene
