#include "plugins/brdf_table.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace wavelit::plugins {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr int kMaxBins = 4096; // per axis: far past MERL's 180, and the product fits in memory
constexpr size_t kHeaderBytes = 3 * sizeof(int32_t);

int binIndex(double fraction, int bins) {
    return std::clamp(int(fraction * bins), 0, bins - 1);
}

// A position between two bin centres: value = (1 − t) v[i0] + t v[i1].
struct BinCoordinate {
    int i0, i1;
    double t;
};

// fraction in [0, 1] of an axis of `bins` bins whose values sit at the bin centres; beyond the
// first and last centre the edge value holds.
BinCoordinate clampedCoordinate(double fraction, int bins) {
    const double x = std::clamp(fraction * bins - 0.5, 0.0, double(bins - 1));
    const int i0 = std::min(int(x), bins - 1);
    return {i0, std::min(i0 + 1, bins - 1), x - i0};
}

// φd is periodic with period π (the fold of reciprocity), so the last bin neighbours the first.
BinCoordinate periodicCoordinate(double fraction, int bins) {
    double x = fraction * bins - 0.5;
    if (x < 0.0) x += bins;
    const int i0 = std::min(int(x), bins - 1);
    return {i0, (i0 + 1) % bins, x - i0};
}

struct HalfDiff {
    double thetaHalf, thetaDiff, phiDiff; // phiDiff folded into [0, π)
};

// Rusinkiewicz's half/difference angles as MERL's reader computes them: h = normalize(wi + wo),
// the difference vector is wi rotated by −φh about the normal, then by −θh about the binormal.
// Both directions are renormalised first: float unit vectors are off by ~1e-7, which tilts h off
// the bisector and made f(wo, wi) and f(wi, wo) differ by 1.3e-5 on a sharp table.
HalfDiff halfDiffOf(const glm::vec3& woFloat, const glm::vec3& wiFloat) {
    const glm::dvec3 wo = glm::normalize(glm::dvec3(woFloat)), wi = glm::normalize(glm::dvec3(wiFloat));
    const glm::dvec3 h = glm::normalize(wo + wi);
    const double thetaH = std::atan2(std::sqrt(h.x * h.x + h.y * h.y), h.z);
    const double phiH = std::atan2(h.y, h.x);
    const glm::dvec3 in(wi);
    const double cp = std::cos(phiH), sp = std::sin(phiH), ct = std::cos(thetaH), st = std::sin(thetaH);
    const double x1 = in.x * cp + in.y * sp, y1 = -in.x * sp + in.y * cp, z1 = in.z;
    const glm::dvec3 d(x1 * ct - z1 * st, y1, x1 * st + z1 * ct);
    double phiD = std::atan2(d.y, d.x);
    if (phiD < 0.0) phiD += kPiD;
    return {thetaH, std::atan2(std::sqrt(d.x * d.x + d.y * d.y), d.z), phiD};
}

std::string withCommas(size_t n) {
    const std::string digits = std::to_string(n);
    std::string out;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

} // namespace

size_t BrdfTable::binOf(const glm::vec3& wo, const glm::vec3& wi) const {
    const HalfDiff a = halfDiffOf(wo, wi);
    const int ih = a.thetaHalf <= 0.0 ? 0 : binIndex(std::sqrt(a.thetaHalf / (0.5 * kPiD)), thetaHalfBins);
    const int id = binIndex(a.thetaDiff / (0.5 * kPiD), thetaDiffBins);
    const int ip = binIndex(a.phiDiff / kPiD, phiDiffBins);
    return size_t(ip) + size_t(phiDiffBins) * (size_t(id) + size_t(thetaDiffBins) * size_t(ih));
}

glm::vec3 BrdfTable::eval(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    // Multilinear between bin centres: continuous in the angles, so a coarse table (the shipped
    // example) integrates to its model's albedo, and the MERL tables look the same.
    const HalfDiff a = halfDiffOf(wo, wi);
    const BinCoordinate h = clampedCoordinate(std::sqrt(a.thetaHalf / (0.5 * kPiD)), thetaHalfBins);
    const BinCoordinate d = clampedCoordinate(a.thetaDiff / (0.5 * kPiD), thetaDiffBins);
    const BinCoordinate p = periodicCoordinate(a.phiDiff / kPiD, phiDiffBins);
    const size_t n = binCount();
    glm::dvec3 sum(0.0);
    for (int k = 0; k < 8; ++k) {
        const double w = ((k & 1) ? h.t : 1.0 - h.t) * ((k & 2) ? d.t : 1.0 - d.t) * ((k & 4) ? p.t : 1.0 - p.t);
        if (w == 0.0) continue;
        const size_t bin = size_t((k & 4) ? p.i1 : p.i0) +
                           size_t(phiDiffBins) * (size_t((k & 2) ? d.i1 : d.i0) +
                                                  size_t(thetaDiffBins) * size_t((k & 1) ? h.i1 : h.i0));
        sum += w * glm::dvec3(f[bin], f[bin + n], f[bin + 2 * n]);
    }
    return glm::vec3(sum);
}

double tableHalfWidthAtNormalView(const BrdfTable& table) {
    // At normal view f depends on θi only (isotropy): a 1D integral of f cosθ sinθ dθ on a grid
    // fine near the normal (θ = (π/2) t², the sqrt spacing of MERL's θh bins), midpoint rule.
    constexpr int kSteps = 4096;
    std::vector<double> cumulative(kSteps + 1, 0.0);
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    for (int i = 0; i < kSteps; ++i) {
        const double t0 = double(i) / kSteps, t1 = double(i + 1) / kSteps, tm = 0.5 * (t0 + t1);
        const double theta = 0.5 * kPiD * tm * tm, dTheta = 0.5 * kPiD * (t1 * t1 - t0 * t0);
        const glm::vec3 wi(float(std::sin(theta)), 0.0f, float(std::cos(theta)));
        const glm::vec3 f = table.eval(n, wi);
        const double luminance = 0.2126 * f.r + 0.7152 * f.g + 0.0722 * f.b;
        cumulative[size_t(i) + 1] = cumulative[size_t(i)] + luminance * std::cos(theta) * std::sin(theta) * dTheta;
    }
    if (!(cumulative.back() > 0.0)) return 0.5 * kPiD;
    const double half = 0.5 * cumulative.back();
    const size_t i = size_t(std::lower_bound(cumulative.begin(), cumulative.end(), half) - cumulative.begin());
    const double t = double(std::max<size_t>(i, 1)) / kSteps;
    return std::clamp(0.5 * kPiD * t * t, 1e-3, 0.5 * kPiD);
}

util::Result<std::shared_ptr<const BrdfTable>> loadMerlBrdf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return util::makeError(util::ErrorKind::NotFound, path, "cannot open the measured BRDF file");
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < kHeaderBytes)
        return util::makeError(util::ErrorKind::Format, path,
                               "not a MERL BRDF file: " + std::to_string(bytes.size()) +
                                   " bytes, shorter than the 12-byte header of bin counts");
    int32_t dims[3];
    std::memcpy(dims, bytes.data(), kHeaderBytes);
    for (int32_t d : dims)
        if (d < 1 || d > kMaxBins)
            return util::makeError(util::ErrorKind::Format, path,
                                   "not a MERL BRDF file: bin counts " + std::to_string(dims[0]) + " x " +
                                       std::to_string(dims[1]) + " x " + std::to_string(dims[2]) +
                                       " (each must be 1 to " + std::to_string(kMaxBins) + ")");
    auto table = std::make_shared<BrdfTable>();
    table->thetaHalfBins = dims[0];
    table->thetaDiffBins = dims[1];
    table->phiDiffBins = dims[2];
    table->file = path;
    const size_t n = table->binCount();
    const size_t expected = kHeaderBytes + 3 * n * sizeof(double);
    if (bytes.size() != expected)
        return util::makeError(util::ErrorKind::Format, path,
                               "wrong size for a MERL BRDF file: expected " + withCommas(expected) +
                                   " bytes for " + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) +
                                   " x " + std::to_string(dims[2]) + " bins, found " + withCommas(bytes.size()));
    table->f.resize(3 * n);
    const char* values = bytes.data() + kHeaderBytes;
    for (size_t i = 0; i < 3 * n; ++i) {
        double v;
        std::memcpy(&v, values + i * sizeof(double), sizeof v);
        if (!std::isfinite(v) || v < 0.0) {
            static const char* kChannel[3] = {"red", "green", "blue"};
            return util::makeError(util::ErrorKind::Invalid, path,
                                   std::string(std::isfinite(v) ? "negative" : "non-finite") + " value " +
                                       std::to_string(v) + " in the " + kChannel[i / n] + " channel at bin " +
                                       std::to_string(i % n) + " (a BRDF is finite and >= 0)");
        }
        table->f[i] = float(v * kMerlScale[i / n]);
    }
    table->halfWidthAtNormalView = tableHalfWidthAtNormalView(*table);
    return std::shared_ptr<const BrdfTable>(std::move(table));
}

std::vector<char> tabulateMerlBrdf(const Brdf& brdf, const BrdfParams& params, int thetaHalfBins,
                                   int thetaDiffBins, int phiDiffBins) {
    const int32_t dims[3] = {thetaHalfBins, thetaDiffBins, phiDiffBins};
    const size_t n = size_t(thetaHalfBins) * thetaDiffBins * phiDiffBins;
    std::vector<char> out(kHeaderBytes + 3 * n * sizeof(double));
    std::memcpy(out.data(), dims, kHeaderBytes);
    for (int ih = 0; ih < thetaHalfBins; ++ih)
        for (int id = 0; id < thetaDiffBins; ++id)
            for (int ip = 0; ip < phiDiffBins; ++ip) {
                const double s = (ih + 0.5) / thetaHalfBins;
                const double thetaH = s * s * 0.5 * kPiD;
                const double thetaD = (id + 0.5) / thetaDiffBins * 0.5 * kPiD;
                const double phiD = (ip + 0.5) / phiDiffBins * kPiD;
                // The inverse of halfDiffOf with φh = 0: the difference vector turned back by θh.
                const glm::dvec3 d(std::sin(thetaD) * std::cos(phiD), std::sin(thetaD) * std::sin(phiD),
                                   std::cos(thetaD));
                const glm::dvec3 h(std::sin(thetaH), 0.0, std::cos(thetaH));
                const glm::dvec3 wi(d.x * std::cos(thetaH) + d.z * std::sin(thetaH), d.y,
                                    -d.x * std::sin(thetaH) + d.z * std::cos(thetaH));
                const glm::dvec3 wo = 2.0 * glm::dot(wi, h) * h - wi;
                const glm::vec3 f = brdf.eval(params, glm::vec3(glm::normalize(wo)), glm::vec3(glm::normalize(wi)));
                const size_t bin = size_t(ip) + size_t(phiDiffBins) * (size_t(id) + size_t(thetaDiffBins) * size_t(ih));
                for (int c = 0; c < 3; ++c) {
                    const double v = double(f[c]) / kMerlScale[size_t(c)];
                    std::memcpy(out.data() + kHeaderBytes + (size_t(c) * n + bin) * sizeof(double), &v, sizeof v);
                }
            }
    return out;
}

} // namespace wavelit::plugins
