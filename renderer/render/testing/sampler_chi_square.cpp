#include "render/testing/sampler_chi_square.h"

#include "render/sampling/sampler_environment.h"
#include "util/rng.h"
#include "wavelet/sphere_map.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::render {
namespace {

// Neighbouring midpoints differing by more than this fraction mark an edge worth refining.
constexpr double kEdgeContrast = 0.05;

} // namespace

util::DirectionChiSquareResult
sphereChiSquare(const std::function<std::optional<glm::vec3>(float, float, float)>& sample,
                const std::function<double(const glm::vec3&)>& pdf,
                const SphereChiSquareOptions& o) {
    const wavelet::OctahedralMap map;
    auto toBin = [&](const glm::dvec3& d) { return o.toBinFrame ? o.toBinFrame(d) : d; };
    auto fromBin = [&](const glm::dvec3& d) { return o.fromBinFrame ? o.fromBinFrame(d) : d; };
    auto pdfAt = [&](glm::dvec2 p) {
        return pdf(glm::vec3(fromBin(map.toDirection(0, p))));
    };
    const int cellSide = 1 << o.cellLevel, fineSide = 1 << o.integrationLevel;
    const int cells = cellSide * cellSide;
    std::vector<double> observed(size_t(cells) + 1, 0.0), expected(size_t(cells) + 1, 0.0);
    util::DirectionChiSquareResult result;

    util::Pcg32 rng(o.seed);
    int outsideSupport = 0;
    for (int s = 0; s < o.samples; ++s) {
        const float u1 = rng.nextFloat();
        const float u2 = rng.nextFloat();
        const float u3 = rng.nextFloat();
        const std::optional<glm::vec3> w = sample(u1, u2, u3);
        if (!w || !std::isfinite(w->x) || !std::isfinite(w->y) || !std::isfinite(w->z)) {
            ++result.invalidSamples;
            observed[size_t(cells)] += 1.0;
            continue;
        }
        if (!(pdf(*w) > 0.0)) {
            ++outsideSupport;
            continue;
        }
        const glm::dvec2 p = octSquarePoint(map, toBin(glm::dvec3(*w)));
        observed[size_t(int(p.y * cellSide)) * size_t(cellSide) + size_t(int(p.x * cellSide))] += 1.0;
    }

    // Midpoints of the integration level, then per-texel refinement where needed.
    std::vector<double> mid(size_t(fineSide) * size_t(fineSide));
    for (int y = 0; y < fineSide; ++y)
        for (int x = 0; x < fineSide; ++x)
            mid[size_t(y) * size_t(fineSide) + size_t(x)] =
                pdfAt({(x + 0.5) / fineSide, (y + 0.5) / fineSide});
    std::vector<glm::dvec3> hot;
    for (const glm::vec3& d : o.hotSpots)
        hot.push_back(glm::normalize(toBin(glm::dvec3(d))));
    const double texelRadius = 2.0 * std::sqrt(4.0 * std::numbers::pi) / fineSide;
    const double texelArea = 4.0 * std::numbers::pi / (double(fineSide) * fineSide);
    double total = 0.0;
    for (int y = 0; y < fineSide; ++y)
        for (int x = 0; x < fineSide; ++x) {
            const double v = mid[size_t(y) * size_t(fineSide) + size_t(x)];
            int depth = 0;
            for (const glm::dvec3& spot : hot) {
                const glm::dvec3 c = map.toDirection(0, {(x + 0.5) / fineSide, (y + 0.5) / fineSide});
                if (std::acos(std::clamp(glm::dot(c, spot), -1.0, 1.0)) < o.hotRadius + texelRadius)
                    depth = o.hotDepth;
            }
            if (o.texelSpotRadius > 0.0) {
                const glm::dvec3 c = map.toDirection(0, {(x + 0.5) / fineSide, (y + 0.5) / fineSide});
                const glm::dvec3 spot = glm::normalize(toBin(glm::dvec3(o.texelSpot)));
                if (std::acos(std::clamp(glm::dot(c, spot), -1.0, 1.0)) < o.texelSpotRadius + texelRadius)
                    depth = std::max(depth, o.texelSpotDepth);
            }
            if (depth == 0) {
                const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
                for (int k = 0; k < 4 && depth == 0; ++k) {
                    if (nx[k] < 0 || ny[k] < 0 || nx[k] >= fineSide || ny[k] >= fineSide)
                        continue;
                    const double n = mid[size_t(ny[k]) * size_t(fineSide) + size_t(nx[k])];
                    if ((n > 0.0) != (v > 0.0) ||
                        std::abs(n - v) > kEdgeContrast * std::max(std::abs(n), std::abs(v)))
                        depth = o.refineDepth;
                }
            }
            double mass;
            if (depth == 0) {
                mass = v * texelArea;
            } else {
                const int side = 1 << depth;
                double sum = 0.0;
                for (int j = 0; j < side; ++j)
                    for (int i = 0; i < side; ++i)
                        sum += pdfAt({(x + (i + 0.5) / side) / fineSide,
                                      (y + (j + 0.5) / side) / fineSide});
                mass = sum / (double(side) * side) * texelArea;
            }
            const int shift = o.integrationLevel - o.cellLevel;
            expected[size_t(y >> shift) * size_t(cellSide) + size_t(x >> shift)] += mass * o.samples;
            total += mass;
        }
    result.integratedPdf = total;
    expected[size_t(cells)] = std::max(0.0, 1.0 - total) * o.samples;
    // A handful of samples in a cell the quadrature saw as empty (a sliver of support between
    // midpoints) gets a token expectation so pooling absorbs it; many still fail the test.
    constexpr double kSliverExpected = 1e-9;
    for (size_t c = 0; c < expected.size(); ++c)
        if (expected[c] <= 0.0 && observed[c] > 0.0)
            expected[c] = kSliverExpected;
    result.chi = util::chiSquareTest(observed, expected);
    if (outsideSupport > 0) {
        result.chi.observedOutsideSupport += outsideSupport;
        result.chi.pValue = 0.0;
    }
    return result;
}

} // namespace wavelit::render
