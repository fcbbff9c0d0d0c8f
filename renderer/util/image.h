// ImageRGB: a linear float RGB raster, row 0 at the top (as stored in EXR files).
// Plain data shared by every layer; reading and writing files lives in scene/image_io.h.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace wavelit::util {

struct ImageRGB {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> pixels; // row-major, width * height

    ImageRGB() = default;
    ImageRGB(int w, int h, glm::vec3 fill = glm::vec3(0.0f))
        : width(w), height(h), pixels(size_t(w) * size_t(h), fill) {}

    bool empty() const { return pixels.empty(); }
    glm::vec3& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
    const glm::vec3& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

// Rec.709 luminance, the weights architecture.md §6 fixes for sampling RGB factors.
inline float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

} // namespace wavelit::util
