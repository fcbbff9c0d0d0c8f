#include "render/sampling/sampler_window.h"

#include "render/sampling/sampler_constants.h"
#include "render/sampling/sampler_environment.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::render {
double ProductWindow::side() const { return std::ldexp(1.0, -k); }

glm::dvec2 ProductWindow::origin() const {
    const double half = std::ldexp(1.0, -(k + 1));
    return {ox * half, oy * half};
}

bool ProductWindow::toLocal(glm::dvec2 p, glm::dvec2& local) const {
    const double scale = std::ldexp(1.0, k);
    const glm::dvec2 o = origin();
    local = {(p.x - o.x) * scale, (p.y - o.y) * scale};
    return local.x >= 0.0 && local.x < 1.0 && local.y >= 0.0 && local.y < 1.0;
}

glm::dvec2 ProductWindow::toGlobal(glm::dvec2 local) const { return origin() + local * side(); }

void ProductWindow::globalCell(int l, int x, int y, int& gl, int& gx, int& gy) const {
    gl = k + l;
    gx = (ox << (l - 1)) + x;
    gy = (oy << (l - 1)) + y;
}

ProductWindow chooseWindow(const wavelet::OctahedralMap& map, const glm::dvec3& axis,
                           double halfAngle, int maxK) {
    if (halfAngle >= kWholeSphereCapAngle || maxK < 1)
        return {};
    const glm::dvec3 a = glm::normalize(axis);
    const glm::dvec3 helper = std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 t = glm::normalize(glm::cross(helper, a));
    const glm::dvec3 b = glm::cross(a, t);
    glm::dvec2 lo = octSquarePoint(map, a), hi = lo;
    for (double fraction : {1.0, kRimInnerRing}) {
        const double theta = fraction * halfAngle;
        for (int i = 0; i < kRimProbes; ++i) {
            const double phi = 2.0 * std::numbers::pi * i / kRimProbes;
            const glm::dvec3 d = std::cos(theta) * a +
                                 std::sin(theta) * (std::cos(phi) * t + std::sin(phi) * b);
            const glm::dvec2 p = octSquarePoint(map, d);
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }
    if (hi.x - lo.x > kMaxCompactExtent || hi.y - lo.y > kMaxCompactExtent)
        return {};
    for (int k = maxK; k >= 1; --k) {
        const double side = std::ldexp(1.0, -k), half = 0.5 * side;
        const int maxOrigin = (1 << (k + 1)) - 2;
        const int ox = std::clamp(int(std::floor(lo.x / half)), 0, maxOrigin);
        const int oy = std::clamp(int(std::floor(lo.y / half)), 0, maxOrigin);
        if (ox * half + side >= hi.x && oy * half + side >= hi.y)
            return {k, ox, oy};
    }
    return {};
}

} // namespace wavelit::render
