// Visibility toward local lights and of a point's own object: the shadow ray of a light texel
// stops at the light, and a convex object's points skip their self-visibility rays exactly.
#include "relight/light_projection.h"
#include "relight/object_occluder.h"
#include "relight/relight_preview.h"
#include "relight/relight_test_support.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace wavelit::relight {
namespace {

// A floor, and a rect light 2 cm under a ceiling (the Cornell box's): the ceiling blocks the
// light's every direction at infinity, so each light texel casts a shadow ray; it must stop at
// the light. Those rays used to run along the texel's centre up to the mean distance of the
// light's samples in it, which overshoots into the ceiling where the centre passes beside the
// light: about half the texels were lost (the box's preview was 8% darker than the tracer).
TEST(RelightLightVisibility, ACeilingAboveTheLightDoesNotShadowIt) {
    scene::Scene open = testing::makeRelightScene();
    open.objects.resize(1); // the ground alone
    open.lighting.lights = {open.lighting.lights[1]}; // the rect
    scene::Light& rect = open.lighting.lights[0];
    rect.position = {0.0f, 1.98f, 0.0f};
    rect.direction = {0.0f, -1.0f, 0.0f};
    rect.size = {0.5f, 0.5f};
    open.camera.position = {0.0f, 1.2f, 2.0f};
    open.camera.target = {0.0f, 0.0f, 0.0f};
    scene::Scene closed = open;
    scene::Object ceiling = open.objects[0];
    ceiling.id = 20;
    ceiling.name = "ceiling";
    ceiling.transform.translation = {0.0f, 2.0f, 0.0f};
    ceiling.transform.rotationDeg = {180.0f, 0.0f, 0.0f};
    closed.objects.push_back(ceiling);
    RelightSettings settings = testing::smallSettings();
    settings.level = 5;
    auto a = RelightPreview::create(open, settings), b = RelightPreview::create(closed, settings);
    ASSERT_TRUE(a && b);
    size_t checked = 0, shadowRays = 0;
    for (size_t i = 0; i < (*a)->points().size(); ++i) {
        ASSERT_EQ((*a)->points()[i], (*b)->points()[i]) << i;
        if (!(*a)->points()[i].hit) continue;
        const glm::vec3 want = (*a)->states()[i].lightTerms[0], got = (*b)->states()[i].lightTerms[0];
        ASSERT_GT(want.x, 0.0f) << i;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-5f * want[c]) << "point " << i;
        shadowRays += (*b)->states()[i].occlusions.empty() ? 0 : 1; // the ceiling blocks the light's texels
        ++checked;
    }
    EXPECT_GT(checked, 100u);
    EXPECT_EQ(shadowRays, checked);
}

// A convex mesh's points need no self-visibility rays: skipping them leaves the same lit texels
// as casting them would (none blocked), front side only for a closed mesh, both for a flat one.
TEST(RelightLightVisibility, ConvexObjectsSkipSelfRaysExactly) {
    const MeshConvexity cube = meshConvexity(*testing::cubeMesh(0.5f));
    EXPECT_TRUE(cube.front);
    EXPECT_FALSE(cube.back);
    const MeshConvexity flat = meshConvexity(*testing::groundMesh(3.0f));
    EXPECT_TRUE(flat.front && flat.back);
    auto fold = std::make_shared<scene::TriangleMesh>(); // a valley: two quads meeting at 90 degrees
    fold->positions = {{-1, 1, -1}, {0, 0, -1}, {0, 0, 1}, {-1, 1, 1}, {1, 1, -1}, {1, 1, 1}};
    fold->indices = {0, 2, 1, 0, 3, 2, 1, 2, 5, 1, 5, 4};
    const MeshConvexity valley = meshConvexity(*fold);
    EXPECT_FALSE(valley.front && valley.back);

    // As placed, and mirrored (a negative scale turns the winding: the box's visible faces are
    // then its triangles' back sides, and convexBack is what applies).
    for (const float mirror : {1.0f, -1.0f}) {
        scene::Scene scene = testing::makeRelightScene();
        scene.objects[1].transform.scale = {mirror, 1.0f, 1.0f};
        RelightSettings settings = testing::smallSettings();
        settings.width = 40;
        settings.height = 32;
        auto preview = RelightPreview::create(scene, settings);
        ASSERT_TRUE(preview);
        const TransferContext ctx = (*preview)->context();
        EXPECT_EQ((*ctx.occluders)[1].convexFront, mirror > 0.0f); // the box
        EXPECT_EQ((*ctx.occluders)[1].convexBack, mirror < 0.0f);
        size_t checked = 0, onBox = 0;
        for (size_t i = 0; i < (*preview)->points().size(); ++i) {
            const PreviewPoint& p = (*preview)->points()[i];
            if (!p.hit) continue;
            const PointState& s = (*preview)->states()[i];
            const TexelBits cast = castOcclusion((*ctx.occluders)[p.object], rayOrigin(p), *ctx.dirs, s.above);
            EXPECT_FALSE(anyBit(cast)) << "point " << i;
            EXPECT_EQ(s.lit, s.above) << "point " << i;
            if (p.object == 1) {
                EXPECT_EQ(p.backFace, mirror < 0.0f) << "point " << i;
            }
            onBox += p.object == 1 ? 1 : 0;
            ++checked;
        }
        EXPECT_GT(checked, 500u);
        EXPECT_GT(onBox, 50u);
    }
}

} // namespace
} // namespace wavelit::relight
