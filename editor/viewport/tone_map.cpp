#include "viewport/tone_map.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace wavelit::editor {
namespace {

// A table over [0, 1] is ~40x faster than std::pow per channel. 16384 entries keep the worst
// error below half an 8-bit step: the curve's steepest slope (12.92 at 0) times 1/16383 times
// 255 is 0.2 of a step.
constexpr int kLutSize = 16384;

float srgbEncode(float c) {
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

const std::array<uint8_t, kLutSize>& srgbTable() {
    static const std::array<uint8_t, kLutSize> table = [] {
        std::array<uint8_t, kLutSize> t{};
        for (int i = 0; i < kLutSize; ++i) {
            float linear = float(i) / float(kLutSize - 1);
            t[size_t(i)] = uint8_t(std::lround(std::clamp(srgbEncode(linear), 0.0f, 1.0f) * 255.0f));
        }
        return t;
    }();
    return table;
}

inline int lookup(const std::array<uint8_t, kLutSize>& table, float linear) {
    if (!(linear > 0.0f)) return 0; // negative, zero and NaN
    if (linear >= 1.0f) return 255;  // +inf included
    return table[size_t(std::lround(linear * float(kLutSize - 1)))];
}

} // namespace

int linearToSrgb8(float linear) { return lookup(srgbTable(), linear); }

QImage toneMap(const util::ImageRGB& image, float exposureEv) {
    if (image.empty()) return {};
    const auto& table = srgbTable();
    const float scale = std::exp2(exposureEv);
    QImage out(image.width, image.height, QImage::Format_RGB32);
    for (int y = 0; y < image.height; ++y) {
        auto* row = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 c = image.at(x, y) * scale;
            row[x] = qRgb(lookup(table, c.r), lookup(table, c.g), lookup(table, c.b));
        }
    }
    return out;
}

} // namespace wavelit::editor
