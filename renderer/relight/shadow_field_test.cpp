// The shadow-field drag (shadow_field.h, drag_cache.h, docs/relighting.md §7.0d): the field is the
// ray-cast occlusion at its samples, the drag cache with an exact mask gives the exact terms, an
// incremental drag equals one step from the same cache, and a far move touches only the region
// the object's old and new bounding cones reach.
#include "relight/relight_preview.h"
#include "relight/relight_test_support.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace wavelit::relight {
namespace {

constexpr size_t kBox = 1; // the near cube in makeRelightScene's objects
constexpr scene::EntityId kBoxId = 4;

double relDiff(const glm::vec3& a, const glm::vec3& b) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(a[c]) - double(b[c])) / std::max(std::abs(double(b[c])), 1e-4));
    return worst;
}

EditSummary move(RelightPreview& preview, scene::Scene& scene, const glm::vec3& to) {
    scene::ChangeSet changes;
    EXPECT_TRUE(changes.setProperty(scene, {scene::EntityKind::Object, kBoxId}, "translation", to));
    EXPECT_TRUE(changes.apply(scene));
    return preview.applyChanges(scene, changes);
}

// (1a) At every sample position the field's mask is the ray-cast one, bit for bit.
TEST(RelightShadowField, MaskAtASampleIsTheRayCastMask) {
    auto preview = RelightPreview::create(testing::makeRelightScene(), testing::smallSettings());
    ASSERT_TRUE(preview);
    ShadowFieldSettings settings;
    settings.shells = 6;
    settings.directionLevel = 3;
    (*preview)->enableShadowField(kBox, settings);
    const ShadowField& field = *(*preview)->shadowField();
    const TransferContext ctx = (*preview)->context();
    const ObjectOccluder& box = (*ctx.occluders)[kBox];
    TexelBits all = makeBits(ctx.dirs->count());
    for (size_t t = 0; t < ctx.dirs->count(); ++t) setBit(all, t);
    size_t blocked = 0;
    for (size_t shell = 0; shell < field.shells(); ++shell)
        for (size_t d = 0; d < field.directions(); ++d) {
            const glm::vec3 offset = field.sampleOffset(shell, d);
            const glm::vec3 origin = box.bounds.centre + offset;
            const TexelBits want = castOcclusion(box, origin, *ctx.dirs, coneTexels(box.bounds, origin, *ctx.dirs, all));
            const uint64_t* got = field.lookup(offset);
            ASSERT_EQ(got, field.sampleMask(shell, d)) << shell << " " << d; // the nearest sample is itself
            for (size_t w = 0; w < want.size(); ++w) ASSERT_EQ(got[w], want[w]) << shell << " " << d;
            blocked += anyBit(want) ? 1 : 0;
        }
    EXPECT_GT(blocked, field.directions()); // the masks are not trivially empty
}

// (1b) With a point's exact (ray-cast) mask — what the field holds at a sample — the drag cache
// gives the exact preview's terms (all coefficients kept: the truncation is the only other
// difference, drag_cache.h; <= 1e-5 relative).
TEST(RelightShadowField, CacheWithTheExactMaskGivesTheExactTerms) {
    RelightSettings settings = testing::smallSettings();
    settings.keep = size_t(1) << (2 * settings.level);
    auto preview = RelightPreview::create(testing::makeRelightScene(), settings);
    ASSERT_TRUE(preview);
    (*preview)->enableShadowField(kBox);
    const TransferContext ctx = (*preview)->context();
    const ObjectOccluder& box = (*ctx.occluders)[kBox];
    const auto& caches = *(*preview)->dragCaches();
    size_t checked = 0, shadowed = 0;
    for (size_t i = 0; i < caches.size(); ++i) {
        if (!caches[i].valid) continue;
        const PreviewPoint& p = (*preview)->points()[i];
        const PointState& exact = (*preview)->states()[i];
        const glm::vec3 origin = rayOrigin(p);
        const TexelBits mask = castOcclusion(box, origin, *ctx.dirs, coneTexels(box.bounds, origin, *ctx.dirs, caches[i].visible));
        PointState s = exact;
        applyDragMask(caches[i], mask.data(), box.bounds, origin, (*preview)->fieldEnvTexels(), s, &box.bvh);
        EXPECT_LE(relDiff(s.envTerm, exact.envTerm), 1e-5) << i;
        EXPECT_LE(relDiff(s.envTerm0, exact.envTerm0), 1e-5) << i;
        ASSERT_EQ(s.lightTerms.size(), exact.lightTerms.size());
        for (size_t k = 0; k < s.lightTerms.size(); ++k) EXPECT_LE(relDiff(s.lightTerms[k], exact.lightTerms[k]), 1e-5) << i << " light " << k;
        ++checked;
        shadowed += anyBit(mask) ? 1 : 0;
    }
    EXPECT_GT(checked, 100u);
    EXPECT_GT(shadowed, 20u);
}

} // namespace
} // namespace wavelit::relight
