#include "cli/convergence_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wavelit::cli {
namespace {

constexpr int kMargin = 40;

void drawLine(util::ImageRGB& img, int x0, int y0, int x1, int y1, glm::vec3 color, int thickness) {
    int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
    int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1, err = dx + dy;
    for (;;) {
        for (int oy = -thickness / 2; oy <= thickness / 2; ++oy)
            for (int ox = -thickness / 2; ox <= thickness / 2; ++ox) {
                int x = x0 + ox, y = y0 + oy;
                if (x >= 0 && y >= 0 && x < img.width && y < img.height) img.at(x, y) = color;
            }
        if (x0 == x1 && y0 == y1) break;
        int e2 = 2 * err;
        if (e2 >= dy) { err += dy; x0 += sx; }
        if (e2 <= dx) { err += dx; y0 += sy; }
    }
}

} // namespace

glm::vec3 curveColor(const std::string& name) {
    if (name == "uniform") return {0.6f, 0.6f, 0.6f};
    if (name == "cosine") return {0.55f, 0.35f, 0.15f};
    if (name == "bsdf") return {0.1f, 0.3f, 0.9f};
    if (name == "env") return {0.1f, 0.7f, 0.2f};
    if (name == "mis") return {0.9f, 0.5f, 0.0f};
    if (name == "wavelet") return {0.85f, 0.05f, 0.1f};
    if (name == "oracle") return {0.0f, 0.0f, 0.0f};
    return {0.5f, 0.0f, 0.6f};
}

util::ImageRGB plotConvergence(const std::vector<Curve>& curves, int width, int height) {
    util::ImageRGB img(width, height, glm::vec3(1.0f));
    double tMin = std::numeric_limits<double>::max(), tMax = 0.0;
    double eMin = std::numeric_limits<double>::max(), eMax = 0.0;
    for (const auto& c : curves)
        for (const auto& p : c.points) {
            if (!(p.seconds > 0.0 && p.error > 0.0)) continue;
            tMin = std::min(tMin, p.seconds); tMax = std::max(tMax, p.seconds);
            eMin = std::min(eMin, p.error); eMax = std::max(eMax, p.error);
        }
    const glm::vec3 axis(0.0f);
    drawLine(img, kMargin, height - kMargin, width - kMargin, height - kMargin, axis, 1);
    drawLine(img, kMargin, kMargin, kMargin, height - kMargin, axis, 1);
    if (tMax <= 0.0) return img;
    // Log-log axes padded to whole decades so the slope (-1/2 for Monte Carlo) reads directly.
    const double lx0 = std::floor(std::log10(tMin)), lx1 = std::max(lx0 + 1, std::ceil(std::log10(tMax)));
    const double ly0 = std::floor(std::log10(eMin)), ly1 = std::max(ly0 + 1, std::ceil(std::log10(eMax)));
    auto px = [&](double t) {
        return kMargin + int((std::log10(t) - lx0) / (lx1 - lx0) * (width - 2 * kMargin));
    };
    auto py = [&](double e) {
        return height - kMargin - int((std::log10(e) - ly0) / (ly1 - ly0) * (height - 2 * kMargin));
    };
    for (double d = lx0; d <= lx1; d += 1.0) {
        int x = px(std::pow(10.0, d));
        drawLine(img, x, height - kMargin, x, height - kMargin + 6, axis, 1);
    }
    for (double d = ly0; d <= ly1; d += 1.0) {
        int y = py(std::pow(10.0, d));
        drawLine(img, kMargin - 6, y, kMargin, y, axis, 1);
    }
    for (size_t i = 0; i < curves.size(); ++i) {
        const auto& c = curves[i];
        for (size_t k = 1; k < c.points.size(); ++k) {
            const auto &a = c.points[k - 1], &b = c.points[k];
            if (a.seconds > 0 && a.error > 0 && b.seconds > 0 && b.error > 0)
                drawLine(img, px(a.seconds), py(a.error), px(b.seconds), py(b.error), c.color, 2);
        }
        const int sx = width - kMargin - 14 * int(curves.size() - i);
        for (int y = 8; y < 18; ++y)
            for (int x = sx; x < sx + 10; ++x) img.at(x, y) = c.color;
    }
    return img;
}

} // namespace wavelit::cli
