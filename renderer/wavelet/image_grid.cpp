#include "wavelet/image_grid.h"

#include "util/check.h"
#include "wavelet/haar.h"

namespace wavelit::wavelet {
namespace {

template <typename F>
util::Result<SquareGrid> toGrid(const util::ImageRGB& image, const std::string& file, F&& value) {
    auto level = levelForSize(image.width, image.height, file);
    if (!level)
        return level.error();
    SquareGrid grid(*level);
    for (size_t i = 0; i < grid.values.size(); ++i)
        grid.values[i] = value(image.pixels[i]);
    if (auto finite = checkFinite(grid, file); !finite)
        return finite.error();
    return grid;
}

} // namespace

util::Result<SquareGrid> channelGrid(const util::ImageRGB& image, int channel,
                                     const std::string& file) {
    WAVELIT_CHECK(channel >= 0 && channel < 3);
    return toGrid(image, file, [channel](const glm::vec3& p) { return double(p[channel]); });
}

util::Result<SquareGrid> luminanceGrid(const util::ImageRGB& image, const std::string& file) {
    return toGrid(image, file, [](const glm::vec3& p) {
        return 0.2126 * double(p.r) + 0.7152 * double(p.g) + 0.0722 * double(p.b);
    });
}

} // namespace wavelit::wavelet
