#include "util/direction_chi_square.h"

#include "util/hemisphere_sampling.h"
#include "util/rng.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace wavelit::util {
namespace {

constexpr double kPiD = 3.14159265358979323846;

struct GridMap {
    Frame frame;
    const DirectionGrid& grid;

    double theta(double t) const { return kPiD * std::pow(t, grid.thetaExponent); }
    double dThetaDt(double t) const {
        return kPiD * grid.thetaExponent * std::pow(t, grid.thetaExponent - 1.0);
    }
    glm::vec3 direction(double t, double phi) const {
        double th = theta(t);
        glm::vec3 local(float(std::sin(th) * std::cos(phi)), float(std::sin(th) * std::sin(phi)),
                        float(std::cos(th)));
        return frame.toWorld(local);
    }
    // Cell index of a direction, or -1 if it is not finite.
    int cell(const glm::vec3& w) const {
        glm::vec3 l = frame.toLocal(w);
        if (!std::isfinite(l.x) || !std::isfinite(l.y) || !std::isfinite(l.z)) return -1;
        double len = std::sqrt(double(l.x) * l.x + double(l.y) * l.y + double(l.z) * l.z);
        double th = std::acos(std::clamp(double(l.z) / len, -1.0, 1.0));
        double t = std::pow(th / kPiD, 1.0 / grid.thetaExponent);
        double phi = std::atan2(double(l.y), double(l.x));
        if (phi < 0.0) phi += 2.0 * kPiD;
        int i = std::min(grid.thetaBins - 1, int(t * grid.thetaBins));
        int j = std::min(grid.phiBins - 1, int(phi / (2.0 * kPiD) * grid.phiBins));
        return i * grid.phiBins + j;
    }
};

struct Rect {
    double t0, dt, phi0, dphi;
};

template <typename F> double gaussLegendre2x2(const F& f, const Rect& r) {
    const double g0 = 0.5 - 0.5 / std::sqrt(3.0), g1 = 0.5 + 0.5 / std::sqrt(3.0);
    double s = f(r.t0 + g0 * r.dt, r.phi0 + g0 * r.dphi) + f(r.t0 + g0 * r.dt, r.phi0 + g1 * r.dphi) +
               f(r.t0 + g1 * r.dt, r.phi0 + g0 * r.dphi) + f(r.t0 + g1 * r.dt, r.phi0 + g1 * r.dphi);
    return 0.25 * s * r.dt * r.dphi;
}

// Depth 6 bounds the work at 4^6 rules per subcell, reached only along discontinuities.
constexpr int kMaxDepth = 6;

// f: the integrand (pdf × Jacobian); density: the pdf alone, whose zeros mark the support (the
// Jacobian's zeros at the poles are no boundary).
template <typename F, typename G>
double integrateAdaptive(const F& f, const G& density, const Rect& r, double whole, int samples,
                         int depth) {
    Rect q[4] = {{r.t0, r.dt / 2, r.phi0, r.dphi / 2},
                 {r.t0 + r.dt / 2, r.dt / 2, r.phi0, r.dphi / 2},
                 {r.t0, r.dt / 2, r.phi0 + r.dphi / 2, r.dphi / 2},
                 {r.t0 + r.dt / 2, r.dt / 2, r.phi0 + r.dphi / 2, r.dphi / 2}};
    double parts[4], sum = 0.0;
    for (int k = 0; k < 4; ++k) sum += parts[k] = gaussLegendre2x2(f, q[k]);
    // A support boundary (the horizon) through the piece: the rule cannot see it converge, so
    // refine to the maximum depth. Detected as corners that disagree on being zero.
    int zeros = 0;
    for (double t : {r.t0, r.t0 + r.dt})
        for (double phi : {r.phi0, r.phi0 + r.dphi}) zeros += density(t, phi) > 0.0 ? 0 : 1;
    bool boundary = zeros != 0 && zeros != 4;
    // Tolerance: 1% of the Poisson noise of this piece's expected count, so quadrature error
    // never moves the statistic; the floor keeps empty pieces from recursing forever.
    double tolerance = 0.01 * std::sqrt(std::max(std::abs(sum), 1.0 / samples) / samples);
    if (depth >= kMaxDepth || (!boundary && std::abs(sum - whole) <= tolerance)) return sum;
    double refined = 0.0;
    for (int k = 0; k < 4; ++k) refined += integrateAdaptive(f, density, q[k], parts[k], samples, depth + 1);
    return refined;
}

} // namespace

DirectionChiSquareResult
directionChiSquare(const std::function<std::optional<glm::vec3>(glm::vec2)>& sample,
                   const std::function<double(const glm::vec3&)>& pdf, const DirectionGrid& grid,
                   int samples, uint64_t seed) {
    GridMap map{Frame::fromNormal(glm::normalize(grid.axis)), grid};
    const int cells = grid.thetaBins * grid.phiBins;
    std::vector<double> observed(cells + 1, 0.0), expected(cells + 1, 0.0);
    DirectionChiSquareResult result;

    int outsideSupport = 0;
    Pcg32 rng(seed);
    for (int s = 0; s < samples; ++s) {
        float u1 = rng.nextFloat(); // two statements: argument order is unspecified in C++
        float u2 = rng.nextFloat();
        glm::vec2 u(u1, u2);
        std::optional<glm::vec3> w = sample(u);
        int c = w ? map.cell(*w) : -1;
        if (c >= 0 && !(pdf(*w) > 0.0)) {
            ++outsideSupport; // drawn where the pdf says it cannot be
            continue;
        }
        if (c < 0) {
            ++result.invalidSamples;
            observed[cells] += 1.0;
        } else {
            observed[c] += 1.0;
        }
    }

    // Each cell: sub×sub subcells, each integrated adaptively (a 2×2 Gauss–Legendre rule,
    // split in four while the split changes the result by more than a small fraction of the
    // cell's own sampling noise; cells cut by the horizon or by a narrow lobe need the splits).
    const double dt = 1.0 / grid.thetaBins, dphi = 2.0 * kPiD / grid.phiBins;
    const int sub = grid.subdivisions;
    auto density = [&](double t, double phi) { return pdf(map.direction(t, phi)); };
    auto integrand = [&](double t, double phi) {
        return density(t, phi) * std::sin(map.theta(t)) * map.dThetaDt(t);
    };
    double total = 0.0;
    for (int i = 0; i < grid.thetaBins; ++i) {
        for (int j = 0; j < grid.phiBins; ++j) {
            double integral = 0.0;
            for (int a = 0; a < sub; ++a) {
                for (int b = 0; b < sub; ++b) {
                    Rect r{(i + double(a) / sub) * dt, dt / sub, (j + double(b) / sub) * dphi,
                           dphi / sub};
                    integral += integrateAdaptive(integrand, density, r,
                                                  gaussLegendre2x2(integrand, r), samples, 0);
                }
            }
            expected[i * grid.phiBins + j] = integral * samples;
            total += integral;
        }
    }
    result.integratedPdf = total;
    expected[cells] = std::max(0.0, 1.0 - total) * samples;
    // Every binned sample has pdf > 0, so a cell with observations but zero integrated mass is a
    // sliver of support the quadrature missed, not a sampler bug: give it a token expectation so
    // the low-count pooling absorbs it.
    constexpr double kSliverExpected = 1e-9;
    // The same holds for the invalid cell: when ∫pdf rounds to ≥ 1, a sampler may still lose a
    // few samples in GGX's far tail (the quadrature cannot resolve mass below ~1e-6); too many
    // invalid samples still fail, as a large deviation of the pooled cell.
    for (int c = 0; c <= cells; ++c)
        if (expected[c] <= 0.0 && observed[c] > 0.0) expected[c] = kSliverExpected;
    result.chi = chiSquareTest(observed, expected);
    if (outsideSupport > 0) {
        result.chi.observedOutsideSupport += outsideSupport;
        result.chi.pValue = 0.0;
    }

    return result;
}

} // namespace wavelit::util
