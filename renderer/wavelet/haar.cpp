#include "wavelet/haar.h"

#include "util/check.h"

#include <cmath>

namespace wavelit::wavelet {

int levelOfIndex(size_t index) {
    int l = 0;
    while ((size_t(1) << (2 * (l + 1))) <= index)
        ++l;
    return l;
}

HaarImage forwardHaar(const SquareGrid& grid) {
    WAVELIT_CHECK(grid.level >= 0 && grid.level <= kMaxLevel);
    const int n = grid.level;
    HaarImage out;
    out.level = n;
    out.coeffs.assign(grid.values.size(), 0.0);
    // Finest scaling coefficients: 2^-n times the texel value (eq 12 with a one-texel square).
    const double finest = std::ldexp(1.0, -n);
    std::vector<double> current(grid.values.size());
    for (size_t i = 0; i < current.size(); ++i)
        current[i] = grid.values[i] * finest;
    std::vector<double> parent;
    for (int l = n - 1; l >= 0; --l) {
        const int side = 1 << l, childSide = side * 2;
        parent.assign(size_t(side) * side, 0.0);
        for (int y = 0; y < side; ++y) {
            for (int x = 0; x < side; ++x) {
                const size_t r0 = size_t(2 * y) * childSide, r1 = r0 + childSide;
                const double child[4] = {current[r0 + 2 * x], current[r0 + 2 * x + 1],
                                         current[r1 + 2 * x], current[r1 + 2 * x + 1]};
                double d[3];
                haarAnalyze(child, parent[size_t(y) * side + x], d);
                const size_t base = detailIndex(l, x, y, 0);
                out.coeffs[base] = d[0];
                out.coeffs[base + 1] = d[1];
                out.coeffs[base + 2] = d[2];
            }
        }
        current.swap(parent);
    }
    out.coeffs[0] = current[0];
    return out;
}

SquareGrid inverseHaar(const HaarImage& image) {
    const int n = image.level;
    std::vector<double> current{image.coeffs[0]}, next;
    for (int l = 0; l < n; ++l) {
        const int side = 1 << l, childSide = side * 2;
        next.assign(size_t(childSide) * childSide, 0.0);
        for (int y = 0; y < side; ++y) {
            for (int x = 0; x < side; ++x) {
                double child[4];
                haarSynthesize(current[size_t(y) * side + x],
                               &image.coeffs[detailIndex(l, x, y, 0)], child);
                const size_t r0 = size_t(2 * y) * childSide, r1 = r0 + childSide;
                next[r0 + 2 * x] = child[0];
                next[r0 + 2 * x + 1] = child[1];
                next[r1 + 2 * x] = child[2];
                next[r1 + 2 * x + 1] = child[3];
            }
        }
        current.swap(next);
    }
    SquareGrid grid(n);
    const double scale = std::ldexp(1.0, n);
    for (size_t i = 0; i < current.size(); ++i)
        grid.values[i] = current[i] * scale;
    return grid;
}

util::Result<int> levelForSize(int width, int height, const std::string& file) {
    using util::ErrorKind;
    const std::string dims = std::to_string(width) + "x" + std::to_string(height);
    if (width != height)
        return util::makeError(ErrorKind::Invalid, file, dims + " is not square");
    if (width <= 0 || (width & (width - 1)) != 0)
        return util::makeError(ErrorKind::Invalid, file, dims + " is not a power of two");
    int n = 0;
    while ((1 << n) < width)
        ++n;
    if (n > kMaxLevel)
        return util::makeError(ErrorKind::Invalid, file,
                               dims + " is larger than the " + std::to_string(1 << kMaxLevel) +
                                   " texels per side the wavelet core supports");
    return n;
}

util::Status checkFinite(const SquareGrid& grid, const std::string& file) {
    const int side = grid.size();
    for (size_t i = 0; i < grid.values.size(); ++i) {
        if (!std::isfinite(grid.values[i])) {
            return util::makeError(util::ErrorKind::Invalid, file,
                                   std::string(std::isnan(grid.values[i]) ? "NaN" : "infinite") +
                                       " texel value",
                                   "texel (" + std::to_string(int(i) % side) + ", " +
                                       std::to_string(int(i) / side) + ")");
        }
    }
    return util::okStatus();
}

} // namespace wavelit::wavelet
