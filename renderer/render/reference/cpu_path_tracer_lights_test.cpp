// Next-event estimation and MIS in the CPU reference tracer against closed forms, on a Lambert
// plane with direct lighting only (bounces = 1) and a black environment: each path's value is
// then the light's irradiance at the point the camera ray hits, times ρ/π. The tests replay the
// camera's jitter (docs/estimator.md "Random numbers") to know that point for every sample.
// Also: light sampling only, BSDF sampling only and MIS agree in the mean on a glossy plane, and
// hard cases (a sun 10^6× the sky, lights lying on surfaces) stay finite.
#include "render/reference/cpu_path_tracer.h"

#include "render/reference/cpu_camera.h"
#include "render/testing/cpu_analytic_scenes.h"
#include "render/testing/cpu_test_tracer.h"
#include "render/testing/pixel_moments.h"
#include "util/image.h"
#include "util/path_sampler.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

namespace wavelit::render {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr float kAlbedo = 0.6f;
// The brief's closed-form tolerance; the per-sample Monte Carlo noise of the area-light cases is
// ≤ 0.3% per pixel after kPasses passes (cos θ varies by < 2% over the lights' cones).
constexpr double kClosedFormTolerance = 0.01;
constexpr int kSize = 32;
constexpr int kPasses = 16;
// Strategies agree within this many combined standard errors (the brief: 3σ).
constexpr double kStrategySigmas = 3.0;

scene::Material lambert() {
    scene::Material m;
    m.baseColor = glm::vec3(kAlbedo);
    return m;
}

RenderOptions options(int bounces) {
    RenderOptions o;
    o.width = kSize;
    o.height = kSize;
    o.bounces = bounces;
    o.seed = 5;
    o.device = DeviceChoice::Cpu;
    return o;
}

// Where the camera ray of (x, y, pass) meets the plane y = 0: the tracer's first two draws.
glm::vec3 cameraHit(const scene::Scene& s, const RenderOptions& o, int x, int y, int pass) {
    util::PathSampler rng(util::PathSampler::seedKey(o.seed), uint32_t(y * o.width + x),
                          uint32_t(pass));
    const auto [jx, jy] = rng.next2D();
    CpuCamera camera(s.camera, o.width, o.height);
    glm::vec3 dir = camera.direction(x, y, jx, jy), origin = camera.origin();
    return origin + dir * (-origin.y / dir.y);
}

struct PixelComparison {
    double maxRelativeError = 0.0;
    double meanRatio = 0.0; // Σ rendered / Σ expected over the compared pixels
    int pixels = 0;
};

// Per pixel: mean of samplePixel over the passes vs the mean of ρ/π E(p) over the same camera
// hit points. `include` may skip pixels by their sample points.
PixelComparison compareWithIrradiance(
    const scene::Scene& s, const CpuPathTracer& tracer, const RenderOptions& o,
    const std::function<double(const glm::vec3&)>& irradiance,
    const std::function<bool(const glm::vec3&)>& include = [](const glm::vec3&) { return true; }) {
    PixelComparison r;
    double sumRendered = 0.0, sumExpected = 0.0;
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            double rendered = 0.0, expected = 0.0;
            bool use = true;
            for (int pass = 0; pass < kPasses; ++pass) {
                glm::vec3 p = cameraHit(s, o, x, y, pass);
                use = use && include(p);
                rendered += tracer.samplePixel(x, y, pass).x;
                expected += kAlbedo / kPiD * irradiance(p);
            }
            if (!use) continue;
            ++r.pixels;
            sumRendered += rendered;
            sumExpected += expected;
            double err = expected > 0.0 ? std::abs(rendered / expected - 1.0) : rendered;
            r.maxRelativeError = std::max(r.maxRelativeError, err);
        }
    r.meanRatio = sumRendered / sumExpected;
    return r;
}

double pointIrradiance(const glm::vec3& light, double power, const glm::vec3& p) {
    glm::dvec3 d = glm::dvec3(light) - glm::dvec3(p);
    double d2 = glm::dot(d, d);
    return power / (4.0 * kPiD * d2) * std::max(0.0, d.y / std::sqrt(d2));
}

TEST(CpuPathTracerLights, LambertPlaneUnderAPointLight) {
    auto s = makePlaneScene(lambert());
    scene::Light l;
    l.type = scene::LightType::Point;
    l.position = glm::vec3(0.3f, 2.0f, -0.5f);
    l.intensity = 50.0f;
    s->lighting.lights.push_back(l);
    const RenderOptions o = options(1);
    auto tracer = makeCpuTestTracer(s, o);
    ASSERT_TRUE(tracer);
    auto r = compareWithIrradiance(*s, *tracer, o, [&](const glm::vec3& p) {
        return pointIrradiance(l.position, l.intensity, p);
    });
    EXPECT_LT(r.maxRelativeError, kClosedFormTolerance);
    std::printf("[ lights     ] point: max per-pixel error %.2e over %d pixels\n",
                r.maxRelativeError, r.pixels);
}

TEST(CpuPathTracerLights, LambertPlaneUnderASun) {
    for (float d : {0.53f, 10.0f}) {
        auto s = makePlaneScene(lambert());
        scene::Light l;
        l.type = scene::LightType::Sun;
        l.direction = glm::normalize(glm::vec3(0.5f, -1.0f, 0.3f));
        l.intensity = 3.0f;
        l.angularDiameterDeg = d;
        s->lighting.lights.push_back(l);
        const RenderOptions o = options(1);
        auto tracer = makeCpuTestTracer(s, o);
        ASSERT_TRUE(tracer);
        const double e = l.intensity * -l.direction.y; // E cos θ: exact for any cone above the horizon
        auto r = compareWithIrradiance(*s, *tracer, o, [&](const glm::vec3&) { return e; });
        EXPECT_NEAR(r.meanRatio, 1.0, kClosedFormTolerance) << "d=" << d;
        if (d < 1.0f) {
            EXPECT_LT(r.maxRelativeError, kClosedFormTolerance);
        }
        std::printf("[ lights     ] sun %.2f deg: image mean / (rho/pi E cos) = %.5f, max pixel "
                    "error %.2e\n", d, r.meanRatio, r.maxRelativeError);
    }
}

TEST(CpuPathTracerLights, FarSphereLightMatchesThePointLight) {
    // With its cone above the horizon a sphere light's irradiance IS the point light's.
    auto s = makePlaneScene(lambert());
    scene::Light l;
    l.type = scene::LightType::Sphere;
    l.position = glm::vec3(0.5f, 3.0f, 0.0f);
    l.radius = 0.05f;
    l.intensity = 200.0f;
    s->lighting.lights.push_back(l);
    const RenderOptions o = options(1);
    auto tracer = makeCpuTestTracer(s, o);
    ASSERT_TRUE(tracer);
    auto r = compareWithIrradiance(*s, *tracer, o, [&](const glm::vec3& p) {
        return pointIrradiance(l.position, l.intensity, p);
    });
    EXPECT_NEAR(r.meanRatio, 1.0, kClosedFormTolerance / 4.0);
    EXPECT_LT(r.maxRelativeError, kClosedFormTolerance);
    std::printf("[ lights     ] sphere r=0.05: mean ratio %.5f, max pixel error %.2e\n",
                r.meanRatio, r.maxRelativeError);
}

// Irradiance at p (on y = 0) from a downward-facing rect light of size w×h centred at c
// (y = c.y), U = +X, V = +Z (light_sampler.h's axes for n = −Y): signed corner form factors.
double rectIrradiance(const glm::vec3& c, float w, float h, double power, const glm::vec3& p) {
    auto corner = [&](double a, double b) {
        const double dist = c.y - p.y, x = a / dist, y = b / dist;
        const double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
        return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * kPiD);
    };
    const double x0 = c.x - p.x - w / 2.0, x1 = x0 + w, z0 = c.z - p.z - h / 2.0, z1 = z0 + h;
    const double f = corner(x1, z1) - corner(x0, z1) - corner(x1, z0) + corner(x0, z0);
    return power / (double(w) * h) * f;
}

TEST(CpuPathTracerLights, RectLightOnItsAxis) {
    auto s = makePlaneScene(lambert());
    // Looking down the light's axis through its back face (which emits nothing) with a narrow
    // view: every pixel sees the plane within 5 cm of the axis.
    s->camera.position = glm::vec3(0.0f, 3.0f, 0.0f);
    s->camera.target = glm::vec3(0.0f);
    s->camera.up = glm::vec3(0.0f, 0.0f, -1.0f);
    s->camera.verticalFovDeg = 2.0f;
    scene::Light l;
    l.type = scene::LightType::Rect;
    l.position = glm::vec3(0.0f, 1.0f, 0.0f);
    l.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    l.size = glm::vec2(1.0f, 0.5f);
    l.intensity = 40.0f;
    s->lighting.lights.push_back(l);
    const RenderOptions o = options(1);
    auto tracer = makeCpuTestTracer(s, o);
    ASSERT_TRUE(tracer);
    auto r = compareWithIrradiance(*s, *tracer, o, [&](const glm::vec3& p) {
        return rectIrradiance(l.position, l.size.x, l.size.y, l.intensity, p);
    });
    EXPECT_NEAR(r.meanRatio, 1.0, kClosedFormTolerance);
    std::printf("[ lights     ] rect 1x0.5 on axis: image mean / closed form = %.5f (E = %.4f)\n",
                r.meanRatio, rectIrradiance(l.position, 1.0f, 0.5f, 40.0, glm::vec3(0.0f)));
}

TEST(CpuPathTracerLights, SpotIsAPointLightInsideAndDarkOutside) {
    auto s = makePlaneScene(lambert());
    scene::Light l;
    l.type = scene::LightType::Spot;
    l.position = glm::vec3(0.0f, 2.0f, 0.0f);
    l.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    l.coneInnerDeg = 20.0f;
    l.coneOuterDeg = 30.0f;
    l.intensity = 50.0f;
    s->lighting.lights.push_back(l);
    const RenderOptions o = options(1);
    auto tracer = makeCpuTestTracer(s, o);
    ASSERT_TRUE(tracer);
    auto angle = [&](const glm::vec3& p) {
        return glm::degrees(std::acos(glm::dot(glm::normalize(p - l.position), l.direction)));
    };
    auto inside = compareWithIrradiance(
        *s, *tracer, o, [&](const glm::vec3& p) { return pointIrradiance(l.position, 50.0, p); },
        [&](const glm::vec3& p) { return angle(p) < l.coneInnerDeg; });
    auto outside = compareWithIrradiance(
        *s, *tracer, o, [](const glm::vec3&) { return 0.0; },
        [&](const glm::vec3& p) { return angle(p) > l.coneOuterDeg; });
    EXPECT_GT(inside.pixels, 20);
    EXPECT_GT(outside.pixels, 20);
    EXPECT_LT(inside.maxRelativeError, kClosedFormTolerance);
    EXPECT_EQ(outside.maxRelativeError, 0.0); // exactly dark: the error is the rendered value
    std::printf("[ lights     ] spot: %d pixels inside (max error %.2e), %d outside (all 0)\n",
                inside.pixels, inside.maxRelativeError, outside.pixels);
}

TEST(CpuPathTracerLights, LightOnlyBsdfOnlyAndMisAgreeOnAGlossyPlane) {
    // Each light sits where the camera sees its mirror image, so BSDF sampling finds it.
    const int passes = 128;
    struct Case {
        const char* name;
        scene::Light light;
    };
    std::vector<Case> cases;
    scene::Light sphere;
    sphere.type = scene::LightType::Sphere;
    sphere.position = glm::vec3(0.0f, 1.0f, -2.0f);
    sphere.intensity = 100.0f;
    sphere.radius = 0.05f;
    cases.push_back({"sphere r=0.05", sphere});
    sphere.radius = 0.5f;
    cases.push_back({"sphere r=0.5", sphere});
    scene::Light rect = sphere;
    rect.type = scene::LightType::Rect;
    rect.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 2.0f));
    rect.size = glm::vec2(1.0f, 0.6f);
    cases.push_back({"rect 1x0.6", rect});
    scene::Light sun;
    sun.type = scene::LightType::Sun;
    sun.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 2.0f));
    sun.intensity = 2.0f;
    sun.angularDiameterDeg = 5.0f;
    cases.push_back({"sun 5deg", sun});
    for (const Case& c : cases) {
        scene::Material ggx;
        ggx.brdf = "ggx";
        ggx.roughness = 0.3f;
        ggx.baseColor = glm::vec3(0.9f);
        auto s = makePlaneScene(ggx);
        s->camera.position = glm::vec3(0.0f, 1.0f, 2.0f);
        s->lighting.lights.push_back(c.light);
        auto tracer = makeCpuTestTracer(s, options(1));
        ASSERT_TRUE(tracer);
        PixelMoments m[3];
        const LightStrategy strategies[3] = {LightStrategy::Mis, LightStrategy::LightOnly,
                                             LightStrategy::BsdfOnly};
        for (int i = 0; i < 3; ++i) {
            tracer->setLightStrategy(strategies[i]);
            m[i] = pixelMoments(*tracer, kSize, kSize, passes);
        }
        for (int i = 1; i < 3; ++i) {
            const double sigma = std::hypot(m[0].standardError, m[i].standardError);
            EXPECT_NEAR(m[i].mean, m[0].mean, kStrategySigmas * sigma)
                << c.name << " strategy " << i;
        }
        EXPECT_GT(m[0].mean, 0.0);
        std::printf("[ lights MIS ] %-13s mean (± s.e.) mis %.4f±%.4f light %.4f±%.4f bsdf "
                    "%.4f±%.4f; variance light/mis %.2f bsdf/mis %.2f\n", c.name, m[0].mean,
                    m[0].standardError, m[1].mean, m[1].standardError, m[2].mean,
                    m[2].standardError, m[1].pixelVariance / m[0].pixelVariance,
                    m[2].pixelVariance / m[0].pixelVariance);
    }
}

TEST(CpuPathTracerLights, HardCasesStayFinite) {
    // A 0.53° sun 10^6× the sky's radiance over a mirror-like and a rough GGX plane, and every
    // light kind lying exactly on the surface, four bounces with roulette.
    for (float roughness : {0.02f, 1.0f}) {
        scene::Material ggx;
        ggx.brdf = "ggx";
        ggx.roughness = roughness;
        auto s = makePlaneScene(ggx);
        s->lighting.environment.intensity = 1.0f;
        scene::Light sun;
        sun.type = scene::LightType::Sun;
        sun.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 1.5f)); // mirrored into the view
        sun.angularDiameterDeg = 0.53f;
        const double halfAngle = 0.5 * 0.53 * kPiD / 180.0;
        sun.intensity = float(1e6 * kPiD * std::sin(halfAngle) * std::sin(halfAngle)); // L = 10^6
        s->lighting.lights.push_back(sun);
        for (scene::LightType type : {scene::LightType::Point, scene::LightType::Sphere,
                                      scene::LightType::Rect, scene::LightType::Spot}) {
            scene::Light l;
            l.type = type;
            l.position = glm::vec3(0.2f, 0.0f, 0.1f); // on the plane
            l.direction = glm::vec3(0.0f, 1.0f, 0.0f); // rect faces up, lying in the plane
            l.radius = 0.3f;
            s->lighting.lights.push_back(l);
        }
        auto tracer = makeCpuTestTracer(s, options(4));
        ASSERT_TRUE(tracer);
        for (int pass = 0; pass < 4; ++pass) ASSERT_TRUE(tracer->renderPass().ok());
        auto img = tracer->image();
        ASSERT_TRUE(img.ok());
        double total = 0.0;
        for (const glm::vec3& p : img->pixels)
            for (int c = 0; c < 3; ++c) {
                ASSERT_TRUE(std::isfinite(p[c])) << "r=" << roughness;
                ASSERT_GE(p[c], 0.0f);
                total += p[c];
            }
        EXPECT_GT(total, 0.0);
    }
}

} // namespace
} // namespace wavelit::render
