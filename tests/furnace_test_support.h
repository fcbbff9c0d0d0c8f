// The white furnace the furnace tests share (furnace_test.cpp, sampler_furnace_test.cpp): a sphere
// in a constant environment L rendered by the CPU reference tracer with bounces = 1, the pixels
// wholly on or off the sphere, and a BRDF's directional albedo E(mu) tabulated by quadrature of the
// C++ BRDF (plugins/testing/brdf_albedo.h), independent of the sampling code under test.
#pragma once

#include "render/testing/cpu_analytic_scenes.h"
#include "render/reference/cpu_camera.h"
#include "render/reference/cpu_surface.h"
#include "render/session/integrator_factory.h"
#include "scene/bvh.h"

#include "plugins/brdf.h"
#include "plugins/brdf_table.h"
#include "plugins/testing/brdf_albedo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

namespace wavelit::furnace_test {

// The acceptance bound: within 1% of the analytic value.
constexpr double kFurnaceTolerance = 0.01;
// Background pixels: float rounding of L × 1 only.
constexpr float kExactTolerance = 1e-6f;
constexpr int kSize = 64;
constexpr int kSubpixels = 4; // per axis, for the expected value of a pixel (view angle varies)

enum class PixelKind { Sphere, Background, Edge };

struct Furnace {
    std::shared_ptr<scene::Scene> scene;
    std::shared_ptr<const scene::Bvh> bvh;
    render::RenderOptions options;

    int size;

    Furnace(const scene::Material& material, glm::vec3 env, int imageSize = kSize)
        : size(imageSize) {
        scene = render::makeFurnaceScene(material, env);
        bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
        options.width = size;
        options.height = size;
        options.bounces = 1;
        options.seed = 3;
        options.device = render::DeviceChoice::Cpu;
    }

    bool hits(const render::CpuCamera& cam, int x, int y, float u, float v,
              render::SurfacePoint* sp = nullptr) const {
        glm::vec3 d = cam.direction(x, y, u, v);
        scene::BvhHit hit;
        if (!scene::intersect(*bvh, cam.origin(), d, 0.0f, std::numeric_limits<float>::max(), hit))
            return false;
        if (sp) *sp = render::surfaceAt(*bvh, hit, cam.origin(), d);
        return true;
    }

    // Pixels wholly on the sphere or wholly off it (corners and centre agree); the silhouette
    // mixes both and has no single expected value.
    std::vector<PixelKind> classify() const {
        render::CpuCamera cam(scene->camera, size, size);
        std::vector<PixelKind> kinds;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                int count = 0;
                for (glm::vec2 j : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1),
                                    glm::vec2(1, 1), glm::vec2(0.5f, 0.5f)})
                    count += hits(cam, x, y, j.x, j.y) ? 1 : 0;
                kinds.push_back(count == 5   ? PixelKind::Sphere
                                : count == 0 ? PixelKind::Background
                                             : PixelKind::Edge);
            }
        return kinds;
    }
};

// E(μ) of a BRDF tabulated by quadrature on s = sqrt(μ) (E changes fastest at grazing μ → 0),
// interpolated linearly.
class AlbedoTable {
public:
    AlbedoTable(const plugins::Brdf& brdf, const plugins::BrdfParams& params) {
        for (int i = 0; i <= kNodes; ++i) {
            double s = std::max(double(i) / kNodes, 1e-3);
            float mu = float(s * s);
            glm::vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
            m_values.push_back(plugins::directionalAlbedo(brdf, params, wo, 128, 128));
        }
    }
    glm::dvec3 operator()(double mu) const {
        double s = std::sqrt(std::clamp(mu, 0.0, 1.0)) * kNodes;
        int i = std::min(int(s), kNodes - 1);
        double f = s - i;
        return m_values[i] * (1.0 - f) + m_values[i + 1] * f;
    }

private:
    static constexpr int kNodes = 64;
    std::vector<glm::dvec3> m_values;
};

// A MERL-layout table of `glossy` (white, roughness r, 24 x 64 x 32 bins like the shipped
// example), written and read back through the file format; nullptr if that fails.
inline std::shared_ptr<const plugins::BrdfTable> glossyTable(float r) {
    const std::vector<char> bytes = plugins::tabulateMerlBrdf(
        *plugins::findBrdf("glossy"), plugins::BrdfParams(glm::vec3(1.0f), r), 24, 64, 32);
    // One name per process (ctest -j runs test processes side by side; a shared path races).
    const std::string path = ::testing::TempDir() + "wavelit_furnace_glossy_table_" +
                             std::to_string(::getpid()) + ".binary";
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    auto table = plugins::loadMerlBrdf(path);
    std::remove(path.c_str());
    return table ? *table : nullptr;
}

inline void expectFinite(const util::ImageRGB& img) {
    for (const glm::vec3& p : img.pixels)
        for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(p[c]));
}

} // namespace wavelit::furnace_test
