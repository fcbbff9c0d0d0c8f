#include "relight/environment_factor.h"

#include "relight/texel_directions.h"
#include "wavelet/equirect_resample.h"
#include "wavelet/haar.h"
#include "wavelet/sphere_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::relight {
namespace {

// The octahedral map seen from the environment's own frame: a world direction w is the env-frame
// direction R(-yaw) w (cpu_environment.h), so env-frame d lands where world R(yaw) d does.
class YawedOctahedralMap final : public wavelet::SphereMap {
public:
    explicit YawedOctahedralMap(double yawDeg)
        : m_cos(std::cos(yawDeg * std::numbers::pi / 180.0)),
          m_sin(std::sin(yawDeg * std::numbers::pi / 180.0)) {}
    int faceCount() const override { return 1; }
    glm::dvec3 toDirection(int face, glm::dvec2 uv) const override {
        const glm::dvec3 w = m_map.toDirection(face, uv); // env-frame d = R(-yaw) w
        return {m_cos * w.x - m_sin * w.z, w.y, m_sin * w.x + m_cos * w.z};
    }
    wavelet::FacePoint toSquare(glm::dvec3 d) const override { // world w = R(yaw) d
        return m_map.toSquare({m_cos * d.x + m_sin * d.z, d.y, -m_sin * d.x + m_cos * d.z});
    }
    double jacobian(int face, glm::dvec2 uv) const override { return m_map.jacobian(face, uv); }
    double texelSolidAngle(int face, int n, int x, int y) const override {
        return m_map.texelSolidAngle(face, n, x, y);
    }

private:
    wavelet::OctahedralMap m_map;
    double m_cos, m_sin;
};

} // namespace

std::shared_ptr<const util::ImageRGB> reduceEquirect(const util::ImageRGB& image, int level) {
    const int w = image.width, h = image.height;
    int b = 1;
    while (w / (2 * b) >= 8 * (1 << level) && w % (2 * b) == 0 && h % (2 * b) == 0) b *= 2;
    auto out = std::make_shared<util::ImageRGB>(w / b, h / b);
    for (int oy = 0; oy < out->height; ++oy)
        for (int ox = 0; ox < out->width; ++ox) {
            glm::dvec3 sum(0.0);
            double weight = 0.0;
            for (int y = oy * b; y < (oy + 1) * b; ++y) {
                // Solid angle of a texel in row y, up to the constant 2 pi / w.
                const double omega = std::cos(std::numbers::pi * y / h) - std::cos(std::numbers::pi * (y + 1) / h);
                for (int x = ox * b; x < (ox + 1) * b; ++x) sum += glm::dvec3(image.at(x, y)) * omega;
                weight += omega * b;
            }
            out->at(ox, oy) = glm::vec3(weight > 0.0 ? sum / weight : glm::dvec3(0.0));
        }
    return out;
}

EnvironmentFactor buildEnvironmentFactor(const scene::Environment& env, int level,
                                         const util::ImageRGB* reduced) {
    EnvironmentFactor f;
    f.level = level;
    const int side = 1 << level;
    const glm::dvec3 scale(1.0); // per unit intensity x tint (environment_factor.h)
    std::array<wavelet::SquareGrid, 3> grids;
    for (auto& g : grids) g = wavelet::SquareGrid(level);
    if (reduced && !reduced->empty()) {
        const YawedOctahedralMap map(env.rotationDeg);
        const util::ImageRGB face = wavelet::resampleEquirect(*reduced, map, level).front();
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                for (int c = 0; c < 3; ++c) grids[size_t(c)].at(x, y) = double(face.at(x, y)[c]) * scale[c];
    } else {
        for (int c = 0; c < 3; ++c) std::fill(grids[size_t(c)].values.begin(), grids[size_t(c)].values.end(), scale[c]);
    }
    for (int c = 0; c < 3; ++c) f.coefficients[size_t(c)] = wavelet::forwardHaar(grids[size_t(c)]).coeffs;
    f.interleaved.resize(f.coefficients[0].size());
    for (size_t i = 0; i < f.interleaved.size(); ++i)
        f.interleaved[i] = glm::vec3(float(f.coefficients[0][i]), float(f.coefficients[1][i]),
                                     float(f.coefficients[2][i]));
    return f;
}

glm::vec3 environmentScale(const scene::Environment& env) { return env.intensity * env.tint; }

glm::vec3 environmentRadiance(const scene::Environment& env, const glm::vec3& dir) {
    if (!env.image || env.image->empty()) return glm::vec3(1.0f);
    constexpr float kPi = 3.14159265358979323846f;
    const float yaw = env.rotationDeg * (kPi / 180.0f);
    const float c = std::cos(yaw), s = std::sin(yaw);
    const float x = c * dir.x - s * dir.z, z = s * dir.x + c * dir.z;
    const float u = 0.5f + std::atan2(z, x) / (2.0f * kPi);
    const float v = std::acos(std::clamp(dir.y, -1.0f, 1.0f)) / kPi;
    const int w = env.image->width, h = env.image->height;
    const float fx = u * float(w), fy = v * float(h);
    const int px = fx > 0.0f ? std::min(int(fx), w - 1) : 0;
    const int py = fy > 0.0f ? std::min(int(fy), h - 1) : 0;
    return env.image->at(px, py);
}

std::vector<glm::vec3> envTexelValues(const EnvironmentFactor& env, const TexelDirections& dirs) {
    std::vector<glm::vec3> out(dirs.count(), glm::vec3(0.0f));
    for (int c = 0; c < 3; ++c) {
        if (env.coefficients[size_t(c)].size() != out.size()) continue; // no environment: zero
        const wavelet::SquareGrid grid = wavelet::inverseHaar(wavelet::HaarImage{env.level, env.coefficients[size_t(c)]});
        for (size_t t = 0; t < out.size(); ++t) out[t][c] = float(grid.values[t] * dirs.texelSolidAngle());
    }
    return out;
}

} // namespace wavelit::relight
