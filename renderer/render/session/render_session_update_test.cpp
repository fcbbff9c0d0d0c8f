// Edits as change sets through RenderSession::applyChanges (architecture.md §5.B "What an edit
// rebuilds"): one test per edit kind on the Vulkan tracer (lavapipe) and the CPU tracer asserts
// what the update rebuilt and uploaded (a light drag: no BVH build, no geometry or texel upload),
// and that the image after the incremental update equals, bit for bit (same seed, same passes),
// the image of a session created from scratch on the edited scene: an update can never render
// stale data unnoticed.
#include "render/session/render_session.h"

#include "scene/scene_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <optional>

namespace wavelit::render {
namespace {

const std::string kScene = std::string(WAVELIT_RESOURCE_DIR) + "/scenes/ring_on_ground.wlscene";
constexpr scene::EntityRef kRing{scene::EntityKind::Object, 1};
constexpr scene::EntityRef kGold{scene::EntityKind::Material, 1};
constexpr scene::EntityRef kSoftbox{scene::EntityKind::Light, 1};
constexpr scene::EntityRef kEnvironment{scene::EntityKind::Environment, scene::kInvalidId};
constexpr scene::EntityRef kCamera{scene::EntityKind::Camera, scene::kInvalidId};
constexpr int kPasses = 2;

RenderOptions options(DeviceChoice device, SamplerKind sampler) {
    RenderOptions o;
    o.width = device == DeviceChoice::Vulkan ? 40 : 24;
    o.height = o.width;
    o.seed = 11;
    o.device = device;
    o.validation = device == DeviceChoice::Vulkan;
    o.sampler = sampler;
    return o;
}

util::ImageRGB render(RenderSession& session) {
    for (int i = 0; i < kPasses; ++i)
        EXPECT_TRUE(session.renderPass().ok());
    auto image = session.image();
    EXPECT_TRUE(image.ok());
    return image.ok() ? std::move(image.value()) : util::ImageRGB{};
}

// Expected counts; std::nullopt: not asserted (the params block also carries the sampler
// tables' layout, which a material edit may or may not change).
struct Expected {
    int bvhBuilds = 0, bvhRefits = 0, geometry = 0, lights = 0, materials = 0, envTexels = 0,
        samplerTables = 0;
    std::optional<int> params = 0;
    int tableBuilds = 0;
    int tablesTurned = 0;
};

// want: what the update rebuilt and uploaded; std::nullopt where the update recreates the
// tracer (its counts are a new tracer's).
void checkEdit(DeviceChoice device, const std::string& property, scene::EntityRef ref,
               scene::PropertyValue value, std::optional<Expected> want,
               SamplerKind sampler = SamplerKind::Wavelet /* the kind with per-material product tables */) {
    if (!std::filesystem::exists(kScene))
        GTEST_SKIP() << kScene << " not present";
    auto loaded = scene::loadScene(kScene);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message();
    const scene::Scene before = *loaded;
    auto session = RenderSession::create(before, options(device, sampler));
    ASSERT_TRUE(session.ok()) << session.error().message();
    // Accumulate something the update must drop; the image before the edit, for the last check.
    const util::ImageRGB old = render(**session);

    scene::ChangeSet changes;
    ASSERT_TRUE(changes.setProperty(before, ref, property, value).ok());
    scene::Scene after = before;
    ASSERT_TRUE(changes.apply(after).ok());
    ASSERT_TRUE((*session)->applyChanges(after, changes).ok());
    const RenderStats stats = (*session)->stats();
    const UpdateCounts& c = stats.lastUpdate;
    SCOPED_TRACE(property + ": " + describeUpdate(c));
    if (want) {
        EXPECT_EQ(c.bvhBuilds, want->bvhBuilds);
        EXPECT_EQ(c.bvhRefits, want->bvhRefits);
        EXPECT_EQ(c.samplerTableBuilds, want->tableBuilds);
        EXPECT_EQ(c.samplerTablesTurned, want->tablesTurned);
    }
    if (want && device == DeviceChoice::Vulkan) {
        EXPECT_EQ(c.geometryUploads, want->geometry);
        EXPECT_EQ(c.lightUploads, want->lights);
        EXPECT_EQ(c.materialUploads, want->materials);
        EXPECT_EQ(c.envTexelUploads, want->envTexels);
        EXPECT_EQ(c.samplerTableUploads, want->samplerTables);
        if (want->params) {
            EXPECT_EQ(c.paramUploads, *want->params);
        }
    }
    EXPECT_EQ(stats.samplesPerPixel, 0); // the update restarted accumulation
    const util::ImageRGB incremental = render(**session);
    EXPECT_EQ((*session)->stats().validationMessages, 0);

    auto fresh = RenderSession::create(after, options(device, sampler));
    ASSERT_TRUE(fresh.ok()) << fresh.error().message();
    const util::ImageRGB expected = render(**fresh);
    ASSERT_EQ(incremental.pixels.size(), expected.pixels.size());
    size_t differing = 0;
    for (size_t i = 0; i < expected.pixels.size(); ++i)
        differing += incremental.pixels[i] != expected.pixels[i];
    EXPECT_EQ(differing, 0u) << "pixels that differ from a session built on the edited scene";

    // The edit is visible: the image before it differs (else the test proves nothing).
    size_t changed = 0;
    for (size_t i = 0; i < old.pixels.size(); ++i)
        changed += old.pixels[i] != expected.pixels[i];
    EXPECT_GT(changed, 0u);
}

// Light: the light buffer only.
Expected lightEdit() { return {.lights = 1}; }
// Material: that material's parameters and its product tables (env tables reused).
Expected materialEdit() {
    return {.materials = 1, .samplerTables = 1, .params = std::nullopt, .tableBuilds = 1};
}
// Object move: that object's triangles refitted, geometry re-sent; no table changes.
Expected moveEdit() { return {.bvhRefits = 1, .geometry = 1}; }
// Environment intensity: the parameters only. The sampler tables are built at intensity 1
// (tablesEnvironment), so they are kept, and so is the per-pixel product cache.
Expected environmentIntensity() { return {.params = 1}; }
// Environment tint: parameters and the sampler tables (env + both materials' product tables
// rebuilt: the tint changes the luminance the tables follow), never the texels.
Expected environmentTint() { return {.samplerTables = 1, .params = 1, .tableBuilds = 3}; }
// Environment rotation: parameters and the sampler tables, none rebuilt (the env tables turned,
// the product tables kept: all env-local), never the texels.
Expected environmentRotation() {
    return {.samplerTables = 1, .params = 1, .tableBuilds = 0, .tablesTurned = 1};
}
// Camera: the params block only.
Expected cameraEdit() { return {.params = 1}; }

TEST(RenderSessionUpdate, LightEditUploadsTheLightsOnlyOnVulkan) {
    checkEdit(DeviceChoice::Vulkan, "intensity", kSoftbox, 150.0f, lightEdit());
}
TEST(RenderSessionUpdate, MaterialEditUploadsThatMaterialAndItsTablesOnVulkan) {
    checkEdit(DeviceChoice::Vulkan, "roughness", kGold, 0.6f, materialEdit());
}
// A BRDF the kernel was not compiled with (it carries only the scene's plugins:
// brdf_shader_source.h): the session recreates the tracer, and the image is still exactly that
// of a session built on the edited scene. (`bsdf`: any kind takes this path, and its kernel is the
// cheapest for lavapipe to compile, ~2 CPU-s against ~35 for `wavelet` when its cache is cold.)
TEST(RenderSessionUpdate, BrdfSwitchToAPluginTheKernelLacksRecreatesTheTracerOnVulkan) {
    checkEdit(DeviceChoice::Vulkan, "brdf", kGold, std::string("blinn"), std::nullopt, SamplerKind::Bsdf);
}
TEST(RenderSessionUpdate, ObjectMoveRefitsTheBvhOnVulkan) {
    checkEdit(DeviceChoice::Vulkan, "translation", kRing, glm::vec3(0.3f, 0.2f, -0.2f), moveEdit());
}
TEST(RenderSessionUpdate, EnvironmentRotationUploadsNoTexelsOnVulkan) {
    checkEdit(DeviceChoice::Vulkan, "rotation", kEnvironment, 90.0f, environmentRotation());
}
TEST(RenderSessionUpdate, EnvironmentIntensityUploadsOnlyTheParamsOnVulkan) {
    checkEdit(DeviceChoice::Vulkan, "intensity", kEnvironment, 2.5f, environmentIntensity());
}
TEST(RenderSessionUpdate, EnvironmentTintRebuildsTheTablesButUploadsNoTexelsOnVulkan) {
    checkEdit(DeviceChoice::Vulkan, "tint", kEnvironment, glm::vec3(1.0f, 0.8f, 0.6f),
              environmentTint());
}
TEST(RenderSessionUpdate, CameraEditUploadsTheParamsOnlyOnVulkan) {
    checkEdit(DeviceChoice::Vulkan, "position", kCamera, glm::vec3(0.5f, 1.5f, 3.0f), cameraEdit());
}

// The CPU tracer uploads nothing; BVH work and table builds are the same.
TEST(RenderSessionUpdate, EveryEditKindOnTheCpuTracer) {
    checkEdit(DeviceChoice::Cpu, "intensity", kSoftbox, 150.0f, lightEdit());
    checkEdit(DeviceChoice::Cpu, "roughness", kGold, 0.6f, materialEdit());
    checkEdit(DeviceChoice::Cpu, "translation", kRing, glm::vec3(0.3f, 0.2f, -0.2f), moveEdit());
    checkEdit(DeviceChoice::Cpu, "rotation", kEnvironment, 90.0f, environmentRotation());
    checkEdit(DeviceChoice::Cpu, "intensity", kEnvironment, 2.5f, environmentIntensity());
    checkEdit(DeviceChoice::Cpu, "tint", kEnvironment, glm::vec3(1.0f, 0.8f, 0.6f),
              environmentTint());
    checkEdit(DeviceChoice::Cpu, "position", kCamera, glm::vec3(0.5f, 1.5f, 3.0f), cameraEdit());
}

} // namespace
} // namespace wavelit::render
