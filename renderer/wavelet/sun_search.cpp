#include "wavelet/sun_search.h"

#include "wavelet/equirect_resample.h"
#include "wavelet/scaling_tree.h"
#include "wavelet/sphere_map.h"
#include "wavelet/square_grid.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace wavelit::wavelet {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMinPeakOverMedian = 50.0;
constexpr double kMaxRegionRadiusRad = 15.0 * kPi / 180.0;

glm::dvec3 texelDirection(int w, int h, int x, int y) {
    const double phi = ((double(x) + 0.5) / double(w) - 0.5) * 2.0 * kPi;
    const double theta = (double(y) + 0.5) / double(h) * kPi;
    return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

double texelSolidAngle(int w, int h, int y) {
    return 2.0 * kPi / double(w) * (std::cos(double(y) / h * kPi) - std::cos(double(y + 1) / h * kPi));
}

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

// Step 1: descend the equal-area energy quadtree into the child with the most energy.
glm::dvec3 brightestLeafDirection(const util::ImageRGB& equirect, int level) {
    const OctahedralMap map;
    const std::vector<util::ImageRGB> faces = resampleEquirect(equirect, map, level);
    SquareGrid grid(level);
    for (int y = 0; y < grid.size(); ++y)
        for (int x = 0; x < grid.size(); ++x) grid.at(x, y) = std::max(0.0, double(util::luminance(faces[0].at(x, y))));
    const ScalingTree tree = ScalingTree::fromGrid(grid);
    int x = 0, y = 0, node = 0;
    for (int l = 0; l < level && tree.nodes[size_t(node)].firstChild >= 0; ++l) {
        const int first = tree.nodes[size_t(node)].firstChild;
        int best = 0;
        for (int c = 1; c < 4; ++c)
            if (tree.nodes[size_t(first + c)].value > tree.nodes[size_t(first + best)].value) best = c;
        node = first + best;
        x = 2 * x + (best & 1);
        y = 2 * y + (best >> 1);
    }
    // fromGrid builds the full pyramid, so the descent always reaches level n.
    const double cell = 1.0 / double(1 << level);
    return map.toDirection(0, {(double(x) + 0.5) * cell, (double(y) + 0.5) * cell});
}

} // namespace

util::Result<SunRegion> findSunRegion(const util::ImageRGB& equirect, int treeLevel) {
    const int w = equirect.width, h = equirect.height;
    if (equirect.empty()) return util::makeError(util::ErrorKind::Invalid, "", "the environment has no map to extract a sun from");
    SunRegion r;
    r.treeDirection = brightestLeafDirection(equirect, treeLevel);

    // Step 2: the peak texel near the leaf (within a few leaf widths), the median, the threshold.
    const double leafAngle = std::sqrt(4.0 * kPi) / double(1 << treeLevel);
    const double searchCos = std::cos(std::min(kPi, 4.0 * leafAngle + 2.0 * kPi / double(h)));
    int px = -1, py = -1;
    std::vector<float> luminances(equirect.pixels.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float l = util::luminance(equirect.at(x, y));
            luminances[size_t(y) * size_t(w) + size_t(x)] = l;
            if (glm::dot(texelDirection(w, h, x, y), r.treeDirection) < searchCos) continue;
            if (px < 0 || l > luminances[size_t(py) * size_t(w) + size_t(px)]) px = x, py = y;
        }
    if (px < 0) return util::makeError(util::ErrorKind::Invalid, "", "the wavelet tree's brightest leaf has no texel near it");
    r.peakLuminance = luminances[size_t(py) * size_t(w) + size_t(px)];
    r.peakDirection = texelDirection(w, h, px, py);
    std::vector<float> sorted = luminances;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    r.medianLuminance = std::max(0.0f, sorted[sorted.size() / 2]);
    if (!(r.peakLuminance > kMinPeakOverMedian * r.medianLuminance))
        return util::makeError(util::ErrorKind::Invalid, "",
                               "no sun in the environment: its brightest compact region peaks at " +
                                   std::to_string(r.peakLuminance) + ", only " +
                                   std::to_string(r.medianLuminance > 0 ? r.peakLuminance / r.medianLuminance : 0.0) +
                                   " x the median (" + std::to_string(r.medianLuminance) + "); a sun needs " +
                                   std::to_string(int(kMinPeakOverMedian)) + " x");
    const double threshold = r.medianLuminance > 0.0 ? std::sqrt(r.peakLuminance * r.medianLuminance)
                                                     : 1e-3 * r.peakLuminance;

    // The region: 8-connected texels above the threshold, x wrapping around.
    std::vector<char> inRegion(luminances.size(), 0);
    std::vector<std::pair<int, int>> stack{{px, py}}, region;
    inRegion[size_t(py) * size_t(w) + size_t(px)] = 1;
    while (!stack.empty()) {
        auto [x, y] = stack.back();
        stack.pop_back();
        region.push_back({x, y});
        if (angleBetween(texelDirection(w, h, x, y), r.peakDirection) > kMaxRegionRadiusRad)
            return util::makeError(util::ErrorKind::Invalid, "",
                                   "no compact sun in the environment: the region brighter than " + std::to_string(threshold) +
                                       " around the peak spans more than 30 degrees");
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int ny = y + dy, nx = (x + dx + w) % w;
                if (ny < 0 || ny >= h) continue;
                const size_t i = size_t(ny) * size_t(w) + size_t(nx);
                if (inRegion[i] || luminances[i] < threshold) continue;
                inRegion[i] = 1;
                stack.push_back({nx, ny});
            }
    }

    // Step 3: the energy centroid and the cap that holds every region texel's centre.
    glm::dvec3 centroid(0.0);
    for (auto [x, y] : region)
        centroid += double(luminances[size_t(y) * size_t(w) + size_t(x)]) * texelSolidAngle(w, h, y) * texelDirection(w, h, x, y);
    r.direction = glm::length(centroid) > 0.0 ? glm::normalize(centroid) : r.peakDirection;
    for (auto [x, y] : region) {
        const double theta = (double(y) + 0.5) / h * kPi;
        const double halfDiagonal = 0.5 * std::hypot(kPi / h, 2.0 * kPi / w * std::sin(theta));
        r.radiusRad = std::max(r.radiusRad, angleBetween(r.direction, texelDirection(w, h, x, y)) + halfDiagonal);
    }
    r.texels = int(region.size());
    return r;
}

} // namespace wavelit::wavelet
