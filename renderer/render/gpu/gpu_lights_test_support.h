// The scene, lights and CPU comparison the GPU light tests share (gpu_lights_test.cpp,
// gpu_lights_reference_test.cpp): a Lambert plane and a GGX sphere under a dim sky, one light of
// each analytic type, and how far the Vulkan tracer's image agrees with the CPU tracer's for the
// same seed. Validation is on everywhere; images are small because lavapipe runs on the test
// machine's CPU. Defined in gpu_lights_scene_test.cpp, which builds into the test executable only
// and so may use render/testing/ and GoogleTest.
#pragma once

#include "render/session/integrator.h"
#include "render/session/render_options.h"
#include "scene/scene.h"
#include "util/image.h"

#include <memory>

namespace wavelit::render::gpu_lights_test {

inline constexpr float kAlbedo = 0.6f; // the plane's red albedo; the closed form's whole albedo

// GPU vs CPU with the same seed. Both draw the same numbers in the same order, so a pixel differs
// only where float rounding (LLVM's sin/cos/acos/sqrt vs libm, fused multiply-adds) flips a branch
// — a cone's rim test, Russian roulette, a shadow ray grazing an edge — and the path diverges.
// kPixelTolerance: relative agreement of a non-diverged pixel (rounding through up to 3 bounces is
// ~1e-5; 1e-3 leaves margin and is the threshold of the light-free CPU/GPU test). kMinMatching:
// at most 2% of pixels may hold a diverged path (measured far fewer). kMeanTolerance: a diverged
// path is another unbiased sample, so means differ only by those few paths' noise; 2% bounds it at
// 4 spp with fireflies from the GGX sphere.
inline constexpr float kPixelTolerance = 1e-3f;
inline constexpr double kMinMatching = 0.98;
inline constexpr double kMeanTolerance = 0.02;

// Vulkan with validation and seed 11, `size` x `size` pixels.
RenderOptions gpuOptions(int bounces, int size);

// A Lambert plane y = 0 and a GGX sphere of radius 0.6 resting on it, a dim constant sky.
std::shared_ptr<scene::Scene> makeLightScene();

// A light of `type` above the plane, aimed at the sphere where it has a direction.
scene::Light makeLight(scene::LightType type);

// `passes` passes of `integrator` (each expected to succeed), then its image.
util::ImageRGB render(Integrator& integrator, int passes);
double meanLuminance(const util::ImageRGB& img);
bool allFinite(const util::ImageRGB& img);

struct Agreement {
    double matching = 0.0; // fraction of pixels within kPixelTolerance
    double gpuMean = 0.0, cpuMean = 0.0;
    int validationMessages = 0;
    bool finite = false;
};

// Renders `scene` on the GPU and the CPU tracer with the same options and compares the images.
Agreement compareWithCpu(const std::shared_ptr<scene::Scene>& scene, int bounces, int size, int passes);

} // namespace wavelit::render::gpu_lights_test
