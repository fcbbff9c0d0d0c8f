#include "render/gpu/precomputed_products.h"

#include "render/sampling/sampler_constants.h"
#include "util/image.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

namespace wavelit::render {

namespace {

int levelOffset(int l) { return ((1 << (2 * l)) - 1) / 3; }

glm::dvec3 octCentre(int bins, int bx, int by) {
    return wavelet::OctahedralMap{}.toDirection(
        0, glm::dvec2((bx + 0.5) / bins, (by + 0.5) / bins));
}

// The bin's canonical lobe: its axis as the normal, seen at normal incidence (any tangent frame
// about the axis will do). brdfCos(d): luminance of BRDF x cos toward env-local d, 0 below the
// horizon — what the pyramid's leaves and the tail moment both weigh the env by.
struct CanonicalLobe {
    const SamplerMaterial& material;
    glm::dvec3 n, t, b;

    CanonicalLobe(const SamplerMaterial& m, const glm::dvec3& axis) : material(m), n(axis) {
        const glm::dvec3 helper = std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
        t = glm::normalize(glm::cross(helper, n));
        b = glm::cross(n, t);
    }
    double brdfCos(const glm::dvec3& d) const {
        const glm::vec3 l(float(glm::dot(d, t)), float(glm::dot(d, b)), float(glm::dot(d, n)));
        if (l.z <= 0.0f)
            return 0.0;
        const glm::vec3 normalIncidence(0.0f, 0.0f, 1.0f);
        return double(util::luminance(material.brdf->eval(material.params, normalIncidence, l) * l.z));
    }
};

} // namespace

int precomputedPyramidFloats(int m) { return levelOffset(m + 1); }

std::vector<float> buildBinPyramid(const SamplerEnvironment& env, const SamplerMaterial& material,
                                   int m, const AxisBin& bin) {
    std::vector<float> out(size_t(precomputedPyramidFloats(m)), 0.0f);
    const int side = 1 << m, level = bin.window.k + m;
    const int x0 = bin.window.ox << (m - 1), y0 = bin.window.oy << (m - 1); // global leaf origin
    const double subSide = double(1 << (level + 1));
    const CanonicalLobe lobe(material, bin.axis);
    float* leaves = out.data() + levelOffset(m);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            double sum = 0.0;
            for (int c = 0; c < 4; ++c) {
                const int sx = 2 * (x0 + x) + (c & 1), sy = 2 * (y0 + y) + (c >> 1);
                const double radiance = env.cellAverage(level + 1, sx, sy);
                if (!(radiance > 0.0))
                    continue;
                const glm::dvec3 d = env.map().toDirection(
                    0, glm::dvec2((sx + 0.5) / subSide, (sy + 0.5) / subSide));
                sum += radiance * lobe.brdfCos(d);
            }
            leaves[y * side + x] = float(0.25 * sum);
        }
    // dsSumPyramid's float sums, in its order.
    for (int l = m - 1; l >= 0; --l) {
        const int sideL = 1 << l, offL = levelOffset(l), offC = levelOffset(l + 1);
        for (int y = 0; y < sideL; ++y)
            for (int x = 0; x < sideL; ++x) {
                const int c0 = offC + 2 * y * (2 * sideL) + 2 * x, c1 = c0 + 2 * sideL;
                out[size_t(offL + y * sideL + x)] = out[size_t(c0)] + out[size_t(c0 + 1)] +
                                                    out[size_t(c1)] + out[size_t(c1 + 1)];
            }
    }
    return out;
}

double binTailMoment(const SamplerEnvironment& env, const SamplerMaterial& material,
                     const AxisBin& bin) {
    const int side = 1 << kTailLevel;
    const CanonicalLobe lobe(material, bin.axis);
    double sum = 0.0;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const glm::dvec2 p((x + 0.5) / side, (y + 0.5) / side);
            glm::dvec2 local;
            if (bin.window.toLocal(p, local))
                continue; // inside the window: the product's part
            const double fcos = lobe.brdfCos(wavelet::OctahedralMap{}.toDirection(0, p));
            sum += double(float(env.cellAverage(kTailLevel, x, y))) * fcos * fcos;
        }
    const double fourPi = 4.0 * std::numbers::pi, cellSolidAngle = fourPi / double(side * side);
    return sum * fourPi * cellSolidAngle;
}

int precomputedBinWords(int m) {
    return (kPrecomputedBinHeaderWords + precomputedPyramidFloats(m) + 1) & ~1;
}

int axisBinLevel(const MaterialProductTables& tables) {
    return std::max(kAxisBinLevel, tables.policy().binLevel);
}

std::vector<AxisBin> axisBins(const MaterialProductTables& tables) {
    const int bins = 1 << axisBinLevel(tables);
    std::vector<AxisBin> out;
    for (int by = 0; by < bins; ++by)
        for (int bx = 0; bx < bins; ++bx) {
            const glm::dvec3 axis = octCentre(bins, bx, by);
            out.push_back({axis, tables.window(tables.binOf(axis))});
        }
    return out;
}

std::vector<uint32_t> buildPrecomputedProducts(const SamplerEnvironment& env,
                                               const SamplerMaterial& material, int m,
                                               const MaterialProductTables& tables) {
    std::vector<uint32_t> out;
    for (const AxisBin& bin : axisBins(tables)) {
        out.push_back(uint32_t(bin.window.k));
        out.push_back(uint32_t(bin.window.ox));
        out.push_back(uint32_t(bin.window.oy));
        out.push_back(std::bit_cast<uint32_t>(float(binTailMoment(env, material, bin))));
        for (float v : buildBinPyramid(env, material, m, bin))
            out.push_back(std::bit_cast<uint32_t>(v));
        if (out.size() % 2 != 0)
            out.push_back(0); // an even stride: every bin's pyramid at the same word parity
    }
    return out;
}

} // namespace wavelit::render
