// lightSeenByPixel skips a pixel's 16 sub-pixel rays when the pixel's cone misses the light's
// bounding cone: the skip must be conservative. Against the plain mean of lightSeenAlongRay over
// the same 16 rays, for every pixel, for a rect, a sphere and a sun light in view, equal bit for bit.
#include "relight/camera_lights.h"
#include "relight/relight_test_support.h"

#include <gtest/gtest.h>

#include <limits>

namespace wavelit::relight {
namespace {

TEST(RelightCameraLights, ConeSkipChangesNoPixel) {
    scene::Scene scene = testing::makeRelightScene();
    scene::Light rect = scene.lighting.lights[1];
    rect.position = {0.3f, 0.6f, 1.5f};
    rect.direction = {0.0f, 0.3f, 1.0f}; // facing the camera
    scene::Light sphere = scene.lighting.lights[2];
    sphere.position = {-0.6f, 0.8f, 1.0f};
    scene::Light sun = scene.lighting.lights[3];
    sun.direction = {0.0f, 0.2f, 1.0f}; // its cone toward the camera: the sky behind the box
    sun.angularDiameterDeg = 20.0f;
    scene.camera.target = {0.0f, 1.5f, 0.0f};
    const int w = 64, h = 48;
    const CameraRays rays(scene.camera, w, h);
    const float inf = std::numeric_limits<float>::infinity();
    for (const scene::Light& light : {rect, sphere, sun}) {
        size_t lit = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                glm::vec3 brute(0.0f);
                for (int j = 0; j < 4; ++j)
                    for (int i = 0; i < 4; ++i)
                        brute += lightSeenAlongRay(light, scene.camera.position,
                                                   rays.direction(x, y, (i + 0.5f) / 4, (j + 0.5f) / 4), inf);
                brute /= 16.0f;
                const glm::vec3 got = lightSeenByPixel(light, scene.camera, rays, x, y, inf);
                ASSERT_EQ(got, brute) << "pixel " << x << "," << y;
                lit += brute != glm::vec3(0.0f) ? 1 : 0;
            }
        EXPECT_GT(lit, 10u) << light.name; // the light is in view (a test of nothing would pass)
        EXPECT_LT(lit, size_t(w * h) / 2) << light.name; // and most pixels are skipped
    }
}

} // namespace
} // namespace wavelit::relight
