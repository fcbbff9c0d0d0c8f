// sceneDigest: what `wavelit-cli merge` compares to refuse parts of different scenes. It must
// follow what renders (properties, mesh data, environment texels, entity order) and ignore what
// does not (names, exposure, where the files lie).
#include "scene/scene_digest.h"

#include "scene/scene_io.h"
#include "scene/scene_io_test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace wavelit::scene {
namespace {

using namespace scene_io_test;

Scene ring() {
    auto s = loadScene((kResources / "scenes/ring_on_ground.wlscene").string());
    EXPECT_TRUE(s.ok()) << s.error().message();
    return *s;
}

TEST(SceneDigest, IsSixteenHexDigitsAndStableAcrossLoads) {
    const std::string d = sceneDigest(ring());
    EXPECT_EQ(d.size(), 16u);
    EXPECT_EQ(d.find_first_not_of("0123456789abcdef"), std::string::npos) << d;
    EXPECT_EQ(sceneDigest(ring()), d);
}

TEST(SceneDigest, IgnoresNamesExposureAndWhereTheFilesLie) {
    const Scene base = ring();
    Scene s = base;
    s.name = "renamed";
    s.materials[0].name = "other";
    s.camera.exposureEv += 2.0f;
    s.objects[0].meshPath = "elsewhere/torus.obj"; // the mesh data is what counts
    EXPECT_EQ(sceneDigest(s), sceneDigest(base));
}

TEST(SceneDigest, FollowsWhatRenders) {
    const Scene base = ring();
    const std::string d = sceneDigest(base);
    Scene s = base;
    s.materials[0].roughness += 0.1f;
    EXPECT_NE(sceneDigest(s), d) << "roughness";
    s = base;
    s.camera.position.x += 0.01f;
    EXPECT_NE(sceneDigest(s), d) << "camera";
    s = base;
    s.lighting.environment.rotationDeg += 1.0f;
    EXPECT_NE(sceneDigest(s), d) << "environment rotation";
    s = base;
    auto texels = std::make_shared<util::ImageRGB>(*s.lighting.environment.image);
    texels->pixels[0] += glm::vec3(1.0f);
    s.lighting.environment.image = texels;
    EXPECT_NE(sceneDigest(s), d) << "environment texels";
    s = base;
    auto mesh = std::make_shared<TriangleMesh>(*s.objects[0].mesh);
    mesh->positions[0].y += 0.001f;
    s.objects[0].mesh = mesh;
    EXPECT_NE(sceneDigest(s), d) << "mesh vertex";
    s = base;
    std::swap(s.objects[0], s.objects[1]);
    EXPECT_NE(sceneDigest(s), d) << "object order";
    s = base;
    Light extra;
    extra.id = s.nextId();
    s.lighting.lights.push_back(extra);
    EXPECT_NE(sceneDigest(s), d) << "a light added";
}

} // namespace
} // namespace wavelit::scene
