#include "render/sampler_environment.h"

#include "render/cpu_environment.h"
#include "util/timer.h"
#include "wavelet/equirect_resample.h"
#include "wavelet/scaling_tree.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::render {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kOneMinusEpsilon = 0x1.fffffffffffffp-1;
constexpr int kHoleSamples = 3;
constexpr double kSupportFloor = 1e-6; // x the mean luminance

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
        const auto faces = wavelet::resampleEquirect(*env.image, s.m_map, n);
        grid = wavelet::SquareGrid(n);
        for (size_t i = 0; i < grid.values.size(); ++i)
            grid.values[i] =
                std::max(0.0, scale * double(util::luminance(faces[0].pixels[i] * tint)));
        // The splat leaves some texels near the poles without a source sample (seen at +Y with
        // 512x256 -> 512^2): fill those from the tracer's own nearest-texel lookup.
        const CpuEnvironment unrotated(scene::Environment{env.path, env.image, 0.0f,
                                                          env.intensity, env.tint});
        const int side = grid.size();
        double sum = 0.0;
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                double& v = grid.at(x, y);
                if (v <= 0.0) {
                    for (int j = 0; j < kHoleSamples; ++j)
                        for (int i = 0; i < kHoleSamples; ++i)
                            v += double(util::luminance(unrotated.radiance(glm::vec3(
                                s.m_map.toDirection(0, {(x + (i + 0.5) / kHoleSamples) / side,
                                                        (y + (j + 0.5) / kHoleSamples) / side})))));
                    v /= double(kHoleSamples * kHoleSamples);
                }
                sum += v;
            }
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
    if (s.m_mips[0].at(0, 0) > 0.0) {
        auto sampler = wavelet::HierarchicalSampler::build(wavelet::ScalingTree::fromGrid(grid));
        if (sampler)
            s.m_fine = std::move(*sampler);
    }
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
    const wavelet::SquareSample s = m_fine->sample(u);
    return {m_map.toDirection(0, s.point), s.pdf / (4.0 * kPi)};
}

double SamplerEnvironment::pdfLocal(const glm::dvec3& local) const {
    if (!m_fine)
        return 0.0;
    return m_fine->pdf(octSquarePoint(m_map, local)) / (4.0 * kPi);
}

size_t SamplerEnvironment::bytes() const {
    size_t b = m_fine ? m_fine->table().size() * sizeof(wavelet::HierarchicalSampler::TableNode) : 0;
    for (const auto& g : m_mips)
        b += g.values.size() * sizeof(double);
    return b;
}

} // namespace wavelit::render
