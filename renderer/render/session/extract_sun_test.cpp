// "Extract sun" (docs/lightmix.md): the sun found through the wavelet tree, its mask, and the
// image staying the same within noise once the sun is a light and the map is masked.
#include "render/testing/median_block_error.h"
#include "render/lights/cpu_environment.h"
#include "render/lights/extract_sun.h"
#include "render/session/render_session.h"
#include "render/testing/light_group_scenes.h"
#include "scene/environment_mask.h"
#include "scene/image_io.h"
#include "scene/scene_io.h"
#include "wavelet/sun_search.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace wavelit::render {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The bundled maps with a sun in the sky. (Studio's brightest compact region is a 16-degree
// softbox and night's an 8-degree lamp: found too; courtyard's bright sky is no compact region.)
constexpr const char* kSunMaps[] = {"city", "sunset"};

double angleDeg(const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) * 180.0 / kPi;
}

scene::Scene groundSceneUnder(const std::string& map, float rotationDeg) {
    auto s = scene::loadScene(lightMixResource("scenes/ring_on_ground.wlscene"));
    EXPECT_TRUE(s.ok()) << s.error().message();
    scene::Scene out = s.ok() ? *s : scene::Scene{};
    out.lightingPath.clear();
    out.lighting.lights.clear();
    scene::Environment& env = out.lighting.environment;
    env = scene::Environment{};
    env.path = "../envmaps/" + map + ".exr";
    env.rotationDeg = rotationDeg;
    auto image = scene::loadImage(lightMixResource("envmaps/" + map + ".exr"));
    EXPECT_TRUE(image.ok()) << image.error().message();
    if (image.ok()) env.image = std::make_shared<const util::ImageRGB>(image->image);
    return out;
}

// The world direction toward the map's brightest texel, found by brute force.
glm::dvec3 bruteForcePeak(const util::ImageRGB& map, float rotationDeg) {
    int bx = 0, by = 0;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
            if (util::luminance(map.at(x, y)) > util::luminance(map.at(bx, by))) bx = x, by = y;
    return mapToWorld(scene::equirectTexelDirection(map.width, map.height, bx, by), rotationDeg);
}

TEST(ExtractSun, SunPointsAtTheMapsPeakWithinItsAngularDiameter) {
    for (const char* map : kSunMaps)
        for (float rotation : {0.0f, 75.0f}) {
            const scene::Scene s = groundSceneUnder(map, rotation);
            ASSERT_TRUE(s.lighting.environment.image);
            auto extracted = extractSun(s, "test.wlscene");
            ASSERT_TRUE(extracted.ok()) << map << ": " << extracted.error().message();
            const scene::Light& sun = extracted->scene.lighting.lights.back();
            EXPECT_EQ(sun.type, scene::LightType::Sun);
            EXPECT_EQ(extracted->lightName, "sun");
            const double offPeak = angleDeg(-glm::dvec3(sun.direction), bruteForcePeak(*s.lighting.environment.image, rotation));
            std::printf("%s rotated %.0f: sun %.3f deg from the peak, diameter %.3f deg, intensity %.4g, %.1f%% of the energy\n",
                        map, rotation, offPeak, sun.angularDiameterDeg, sun.intensity, 100.0 * extracted->energyFraction);
            EXPECT_LE(offPeak, sun.angularDiameterDeg) << map;
            EXPECT_GT(sun.angularDiameterDeg, 0.0f);
            EXPECT_LT(sun.angularDiameterDeg, 30.0f);
            EXPECT_NEAR(util::luminance(sun.color), 1.0f, 1e-4f);
        }
}

TEST(ExtractSun, MaskMovesTheSunsEnergyIntoTheLight) {
    const scene::Scene s = groundSceneUnder("city", 30.0f);
    auto extracted = extractSun(s, "test.wlscene");
    ASSERT_TRUE(extracted.ok()) << extracted.error().message();
    const scene::Environment& before = s.lighting.environment;
    const scene::Environment& after = extracted->scene.lighting.environment;
    const scene::Light& sun = extracted->scene.lighting.lights.back();
    // Brute force: the luminance energy the mask removed, weighted by the cosine to the sun, is
    // the sun's irradiance (its luminance, colour normalised to 1).
    const util::ImageRGB& map = *before.image;
    double removed = 0.0;
    int masked = 0;
    const glm::dvec3 axis = glm::normalize(glm::dvec3(after.maskDirection));
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            const glm::vec3 a = map.at(x, y), b = after.image->at(x, y);
            if (a == b) continue;
            ASSERT_EQ(b, glm::vec3(0.0f)) << "texel " << x << "," << y << " changed but is not black";
            const glm::dvec3 d = scene::equirectTexelDirection(map.width, map.height, x, y);
            removed += util::luminance(a) * scene::equirectTexelSolidAngle(map.width, map.height, y) * glm::dot(d, axis);
            ++masked;
        }
    std::printf("mask: %d texels, radius %.3f deg, removed irradiance %.5g, sun intensity %.5g\n", masked,
                after.maskRadiusDeg, removed, sun.intensity);
    EXPECT_GT(masked, 0);
    EXPECT_NEAR(sun.intensity, removed, 1e-3 * removed);
    // The lookup both tracers' environments share sees black toward the sun.
    const CpuEnvironment lookup(after);
    EXPECT_EQ(lookup.radiance(glm::vec3(-sun.direction)), glm::vec3(0.0f));
    EXPECT_GT(util::luminance(CpuEnvironment(before).radiance(glm::vec3(-sun.direction))), 0.0f);
    // Extracting twice is refused, naming the mask.
    auto again = extractSun(extracted->scene, "test.wlscene");
    ASSERT_FALSE(again.ok());
    EXPECT_NE(again.error().message().find("already has a mask"), std::string::npos) << again.error().message();
}

TEST(ExtractSun, NoSunIsRefused) {
    const scene::Scene s = groundSceneUnder("courtyard", 0.0f);
    auto extracted = extractSun(s, "test.wlscene");
    ASSERT_FALSE(extracted.ok());
    std::printf("%s\n", extracted.error().message().c_str());
    EXPECT_NE(extracted.error().message().find("test.wlscene"), std::string::npos);
    scene::Scene constant = s;
    constant.lighting.environment = scene::Environment{};
    auto none = extractSun(constant, "test.wlscene");
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message().find("constant"), std::string::npos) << none.error().message();
    // The place is where the environment sits in that kind of file.
    EXPECT_EQ(none.error().where, "/lighting/environment");
    auto inSetup = extractSun(constant, "test.wllight");
    ASSERT_FALSE(inSetup.ok());
    EXPECT_EQ(inSetup.error().where, "/environment");
    EXPECT_EQ(inSetup.error().file, "test.wllight");
}

// The saved mask round-trips through a *.wllight and the loader applies it to the map; a mask
// with no map or no direction is a clear error naming the file and key.
TEST(ExtractSun, MaskIsSavedLoadedAndValidated) {
    const scene::Scene s = groundSceneUnder("city", 0.0f);
    auto extracted = extractSun(s, "test.wlscene");
    ASSERT_TRUE(extracted.ok()) << extracted.error().message();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "wavelit_extract_sun_test";
    std::filesystem::create_directories(dir);
    scene::LightingSetup setup = extracted->scene.lighting;
    setup.environment.path = lightMixResource("envmaps/city.exr");
    setup.environment.path = std::filesystem::proximate(setup.environment.path, dir).generic_string();
    const std::string file = (dir / "extracted.wllight").string();
    ASSERT_TRUE(scene::saveLightingSetup(setup, file).ok());
    auto loaded = scene::loadLightingSetup(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message();
    EXPECT_EQ(loaded->environment.maskRadiusDeg, setup.environment.maskRadiusDeg);
    ASSERT_TRUE(loaded->environment.image);
    EXPECT_EQ(loaded->environment.image->pixels, extracted->scene.lighting.environment.image->pixels);

    setup.environment.path.clear();
    ASSERT_TRUE(scene::saveLightingSetup(setup, file).ok());
    auto noMap = scene::loadLightingSetup(file);
    ASSERT_FALSE(noMap.ok());
    EXPECT_NE(noMap.error().message().find("no map to mask"), std::string::npos) << noMap.error().message();
    EXPECT_NE(noMap.error().message().find("extracted.wllight"), std::string::npos);
    std::filesystem::remove_all(dir);
}

double meanLuminance(const util::ImageRGB& img) {
    double sum = 0.0;
    for (const glm::vec3& p : img.pixels) sum += util::luminance(p);
    return sum / double(img.pixels.size());
}

util::ImageRGB renderImage(const scene::Scene& scene, uint64_t seed, DeviceChoice device, int passes) {
    RenderOptions o;
    o.width = 48;
    o.height = 36;
    o.bounces = 3;
    o.seed = seed;
    o.sampler = SamplerKind::Mis;
    o.device = device;
    o.validation = device == DeviceChoice::Vulkan;
    auto session = RenderSession::create(scene, o);
    EXPECT_TRUE(session.ok()) << session.error().message();
    if (!session.ok()) return {};
    for (int pass = 0; pass < passes; ++pass) {
        EXPECT_TRUE((*session)->renderPass().ok());
    }
    if (device == DeviceChoice::Vulkan) {
        EXPECT_EQ((*session)->stats().validationMessages, 0);
    }
    return *(*session)->image();
}

// Median 4x4-block error <= 2x the seed-to-seed figure, means within 3%.
void expectSameWithinNoise(const scene::Scene& before, const scene::Scene& after, DeviceChoice device, int passes,
                           const char* what) {
    const util::ImageRGB b1 = renderImage(before, 1, device, passes), b2 = renderImage(before, 2, device, passes);
    const util::ImageRGB a1 = renderImage(after, 3, device, passes), a2 = renderImage(after, 4, device, passes);
    ASSERT_FALSE(b1.empty() || b2.empty() || a1.empty() || a2.empty());
    const double seedToSeed = std::max(medianBlockError(b1, b2), medianBlockError(a1, a2));
    const double error = medianBlockError(b1, a1);
    const double mb = meanLuminance(b1), ma = meanLuminance(a1);
    std::printf("%s: median 4x4-block error %.5f, seed-to-seed %.5f (before %.5f, after %.5f); means %.5f before, "
                "%.5f after (%+.2f%%)\n",
                what, error, seedToSeed, medianBlockError(b1, b2), medianBlockError(a1, a2), mb, ma,
                100.0 * (ma - mb) / mb);
    EXPECT_LE(error, 2.0 * seedToSeed) << what;
    EXPECT_GT(mb, 0.0) << what;
    EXPECT_NEAR(ma, mb, 0.03 * mb) << what;
}

// The acceptance test: the converged image after "Extract sun" matches the one before within
// noise, on the CPU reference tracer and on the Vulkan tracer (both read the masked map).
TEST(ExtractSun, ImageStaysTheSameWithinNoise) {
    const scene::Scene before = groundSceneUnder("city", 30.0f);
    auto extracted = extractSun(before, "test.wlscene");
    ASSERT_TRUE(extracted.ok()) << extracted.error().message();
    expectSameWithinNoise(before, extracted->scene, DeviceChoice::Cpu, 64, "extract sun, CPU");
}

TEST(ExtractSun, ImageStaysTheSameWithinNoiseOnVulkan) {
    const scene::Scene before = groundSceneUnder("city", 30.0f);
    auto extracted = extractSun(before, "test.wlscene");
    ASSERT_TRUE(extracted.ok()) << extracted.error().message();
    expectSameWithinNoise(before, extracted->scene, DeviceChoice::Vulkan, 32, "extract sun, Vulkan");
}

} // namespace
} // namespace wavelit::render
