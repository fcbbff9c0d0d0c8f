#include "render/sampling/sampler_environment.h"

#include "render/lights/cpu_environment.h"
#include "util/parallel_for.h"
#include "util/timer.h"
#include "wavelet/scaling_tree.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace wavelit::render {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kOneMinusEpsilon = 0x1.fffffffffffffp-1;
constexpr int kLookups = 3;
constexpr double kSupportFloor = 1e-6; // x the mean luminance

// Steps per octahedral texel side when walking an equirect texel's edges.
constexpr int kEdgeStepsPerTexel = 16;
constexpr int kMaxEdgeSteps = 256;

// Raises every octahedral texel that an equirect texel's boundary crosses to that texel's
// luminance (why: build()). Rows run on `threads` threads, each raising its own zeroed copy of the
// grid, merged by max at the end: max is order-free and every value is >= 0, so the grid is the
// same bit for bit whatever the thread count. The meridian between texels x - 1 and x is walked
// once, at the larger of their two values (the same points both texels' walks visit: p1 of x - 1
// and p0 of x are the same double), and every sine and cosine is computed once per row or once
// per map; each point's direction and octahedral texel are the same doubles as walking each
// texel's four edges on its own. The whole build of a 512 x 256 map: 0.76-0.84 -> 0.27-0.37 s
// on 2 cores, 0.52 s on one (issue 12: the first frame's floor; docs/performance.md).
void raiseAlongEquirectEdges(const util::ImageRGB& image, double scale, const glm::vec3& tint,
                             const wavelet::OctahedralMap& map, wavelet::SquareGrid& grid,
                             int threads) {
    const int w = image.width, h = image.height, side = grid.size();
    const double cellAngle = std::sqrt(4.0 * kPi) / side;
    std::vector<double> cosMeridian(size_t(w) + 1), sinMeridian(size_t(w) + 1);
    for (int e = 0; e <= w; ++e) {
        const double phi = 2.0 * kPi * (double(e) / w - 0.5);
        cosMeridian[size_t(e)] = std::cos(phi);
        sinMeridian[size_t(e)] = std::sin(phi);
    }
    const size_t workers = util::parallelWorkers(size_t(h), threads);
    std::vector<std::vector<double>> raised(workers, std::vector<double>(grid.values.size(), 0.0));
    util::parallelForWorkers(size_t(h), threads, [&](size_t worker, size_t row) {
        std::vector<double>& out = raised[worker];
        auto raise = [&](double sinTheta, double cosTheta, double cosPhi, double sinPhi,
                         double value) {
            const glm::dvec3 d(sinTheta * cosPhi, cosTheta, sinTheta * sinPhi);
            const glm::dvec2 p = glm::min(map.toSquare(d).uv, glm::dvec2(kOneMinusEpsilon));
            double& v = out[size_t(std::min(int(p.y * side), side - 1)) * size_t(side) +
                            size_t(std::min(int(p.x * side), side - 1))];
            v = std::max(v, value);
        };
        const int y = int(row);
        const double t0 = kPi * y / h, t1 = kPi * (y + 1) / h;
        // Meridian edges span t1 - t0; latitude edges span 2 pi / w x sin(theta).
        const int nt = std::clamp(int(std::ceil(kEdgeStepsPerTexel * (t1 - t0) / cellAngle)), 2,
                                  kMaxEdgeSteps);
        const double arc = 2.0 * kPi / w * std::max(std::sin(t0), std::sin(t1));
        const int np =
            std::clamp(int(std::ceil(kEdgeStepsPerTexel * arc / cellAngle)), 2, kMaxEdgeSteps);
        std::vector<double> values(static_cast<size_t>(w));
        for (int x = 0; x < w; ++x)
            values[size_t(x)] =
                std::max(0.0, scale * double(util::luminance(image.at(x, y) * tint)));
        for (int i = 0; i <= nt; ++i) {
            const double t = t0 + (t1 - t0) * i / nt;
            const double sinT = std::sin(t), cosT = std::cos(t);
            for (int e = 0; e <= w; ++e) {
                const double left = e > 0 ? values[size_t(e) - 1] : 0.0;
                const double right = e < w ? values[size_t(e)] : 0.0;
                raise(sinT, cosT, cosMeridian[size_t(e)], sinMeridian[size_t(e)],
                      std::max(left, right));
            }
        }
        const double sinT0 = std::sin(t0), cosT0 = std::cos(t0);
        const double sinT1 = std::sin(t1), cosT1 = std::cos(t1);
        for (int x = 0; x < w; ++x) {
            const double p0 = 2.0 * kPi * (double(x) / w - 0.5), p1 = 2.0 * kPi * (double(x + 1) / w - 0.5);
            for (int i = 0; i <= np; ++i) {
                const double ph = p0 + (p1 - p0) * i / np;
                const double cosPh = std::cos(ph), sinPh = std::sin(ph);
                raise(sinT0, cosT0, cosPh, sinPh, values[size_t(x)]);
                raise(sinT1, cosT1, cosPh, sinPh, values[size_t(x)]);
            }
        }
    });
    for (const std::vector<double>& part : raised)
        for (size_t i = 0; i < part.size(); ++i)
            grid.values[i] = std::max(grid.values[i], part[i]);
}

} // namespace

glm::dvec2 octSquarePoint(const wavelet::OctahedralMap& map, const glm::dvec3& d) {
    return glm::min(map.toSquare(d).uv, glm::dvec2(kOneMinusEpsilon));
}

SamplerEnvironment SamplerEnvironment::build(const scene::Environment& env,
                                             const SamplerEnvironmentOptions& options) {
    util::Timer timer;
    SamplerEnvironment s;
    const double yaw = double(env.rotationDeg) * (kPi / 180.0);
    // The same float rounding as CpuEnvironment, so both frames agree to float precision.
    s.m_cosYaw = double(std::cos(float(yaw)));
    s.m_sinYaw = double(std::sin(float(yaw)));
    const double scale = double(env.intensity);
    const glm::vec3 tint = env.tint;

    wavelet::SquareGrid grid;
    if (env.image && !env.image->empty()) {
        const int h = env.image->height;
        const int n = std::clamp(int(std::ceil(std::log2(double(std::max(h, 1))))) + 1,
                                 options.minLevel, options.maxLevel);
        // Each texel takes the MAX of the tracer's own nearest-texel lookup (cpu_environment.h)
        // over kLookups^2 points: a conservative map, so no part of a bright equirect texel (a
        // sun) sits in an octahedral texel whose density is the sky's. An energy-preserving
        // splat (wavelet/equirect_resample.h) spreads a sun over texels it only partly covers
        // and leaves the rest of its equirect texel at sky density: those rare draws carry 1e6 x
        // weights, a heavy tail the tests saw as a 5% low mean at 2e4 samples.
        grid = wavelet::SquareGrid(n);
        scene::Environment unrotatedEnv = env;
        unrotatedEnv.rotationDeg = 0.0f;
        const CpuEnvironment unrotated(unrotatedEnv);
        const int side = grid.size();
        const int threads = util::threadsOrHardware(options.threads);
        // Rows in parallel: each texel is its own lookups' max, whoever computes it.
        util::parallelFor(size_t(side), threads, [&](size_t row) {
            const int y = int(row);
            for (int x = 0; x < side; ++x) {
                double v = 0.0;
                for (int j = 0; j < kLookups; ++j)
                    for (int i = 0; i < kLookups; ++i)
                        v = std::max(v, double(util::luminance(unrotated.radiance(glm::vec3(
                                            s.m_map.toDirection(0, {(x + (i + 0.5) / kLookups) / side,
                                                                    (y + (j + 0.5) / kLookups) / side}))))));
                grid.at(x, y) = v;
            }
        });
        double sum = 0.0;
        // Lookups inside a texel miss the slivers where an equirect texel's edge cuts across it
        // (measured: the 10^6 sun's texel still held octahedral texels at sky density, pdf
        // 0.0014 vs 860 inside one equirect texel, and the env-table samplers read 3-5% low).
        // So also walk every equirect texel's boundary at a fraction of an octahedral texel and
        // raise each octahedral texel it crosses to that equirect texel's luminance: a texel
        // that meets an equirect texel either holds lookup points inside it or is crossed by its
        // boundary, so the map bounds the lookup everywhere up to slivers shorter than the step.
        raiseAlongEquirectEdges(*env.image, scale, tint, s.m_map, grid, threads);
        for (double v : grid.values)
            sum += v;
        // Full support for the env technique wherever the environment may be non-zero: a floor
        // far below anything that matters for variance.
        const double floor = kSupportFloor * sum / double(grid.values.size());
        for (double& v : grid.values)
            v = std::max(v, floor);
    } else {
        grid = wavelet::SquareGrid(options.minLevel,
                                   std::max(0.0, scale * double(util::luminance(tint))));
    }
    s.m_level = grid.level;
    s.m_mips.resize(size_t(grid.level) + 1);
    s.m_mips[size_t(grid.level)] = grid;
    for (int l = grid.level - 1; l >= 0; --l) {
        const wavelet::SquareGrid& fine = s.m_mips[size_t(l) + 1];
        wavelet::SquareGrid& coarse = s.m_mips[size_t(l)];
        coarse = wavelet::SquareGrid(l);
        for (int y = 0; y < coarse.size(); ++y)
            for (int x = 0; x < coarse.size(); ++x)
                coarse.at(x, y) = 0.25 * (fine.at(2 * x, 2 * y) + fine.at(2 * x + 1, 2 * y) +
                                          fine.at(2 * x, 2 * y + 1) + fine.at(2 * x + 1, 2 * y + 1));
    }
    {
        // Equal-area texels: every one covers 4 pi / N^2 sr.
        double sum = 0.0, sumSquares = 0.0;
        for (double v : grid.values) {
            sum += v;
            sumSquares += v * v;
        }
        const double texelSolidAngle = 4.0 * kPi / double(grid.values.size());
        s.m_effectiveSolidAngle = sumSquares > 0.0 ? texelSolidAngle * sum * sum / sumSquares : 0.0;
    }
    s.m_exact = EquirectEnvSampler::build(env);
    s.m_lookup.emplace(env);
    if (s.m_mips[0].at(0, 0) > 0.0 && s.m_exact.hasLight()) {
        auto sampler = wavelet::HierarchicalSampler::build(wavelet::ScalingTree::fromGrid(grid));
        if (sampler)
            s.m_fine = std::move(*sampler);
    }
    s.m_buildSeconds = timer.seconds();
    return s;
}

SamplerEnvironment SamplerEnvironment::rotatedTo(const scene::Environment& env) const {
    util::Timer timer;
    SamplerEnvironment s = *this;
    const double yaw = double(env.rotationDeg) * (kPi / 180.0);
    s.m_cosYaw = double(std::cos(float(yaw))); // as build()
    s.m_sinYaw = double(std::sin(float(yaw)));
    s.m_lookup.emplace(env);
    s.m_buildSeconds = timer.seconds();
    return s;
}

double SamplerEnvironment::cellAverage(int l, int x, int y) const {
    if (l > m_level) {
        const int shift = l - m_level;
        return m_mips[size_t(m_level)].at(x >> shift, y >> shift);
    }
    return m_mips[size_t(l)].at(x, y);
}

glm::dvec3 SamplerEnvironment::toLocal(const glm::dvec3& d) const {
    return {m_cosYaw * d.x - m_sinYaw * d.z, d.y, m_sinYaw * d.x + m_cosYaw * d.z};
}

glm::dvec3 SamplerEnvironment::toWorld(const glm::dvec3& d) const {
    return {m_cosYaw * d.x + m_sinYaw * d.z, d.y, -m_sinYaw * d.x + m_cosYaw * d.z};
}

wavelet::DirectionSample SamplerEnvironment::sampleLocal(glm::dvec2 u) const {
    double pdf = 0.0;
    const glm::dvec3 d = m_exact.sampleLocal(u, pdf);
    return {d, pdf};
}

size_t SamplerEnvironment::bytes() const {
    size_t b = m_fine ? m_fine->table().size() * sizeof(wavelet::HierarchicalSampler::TableNode) : 0;
    for (const auto& g : m_mips)
        b += g.values.size() * sizeof(double);
    b += m_exact.bytes();
    return b;
}

} // namespace wavelit::render
