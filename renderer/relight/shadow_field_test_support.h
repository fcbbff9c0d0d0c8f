// What the shadow-field tests share (shadow_field_test.cpp, shadow_field_own_surface_test.cpp):
// the near box of makeRelightScene and a translation of it applied to a preview.
#pragma once

#include "relight/relight_preview.h"

#include <gtest/gtest.h>

namespace wavelit::relight::testing {

inline constexpr size_t kBox = 1; // the near cube in makeRelightScene's objects
inline constexpr scene::EntityId kBoxId = 4;

// Translates the box of `scene` to `to` and applies the edit to `preview`.
inline EditSummary moveBox(RelightPreview& preview, scene::Scene& scene, const glm::vec3& to) {
    scene::ChangeSet changes;
    EXPECT_TRUE(changes.setProperty(scene, {scene::EntityKind::Object, kBoxId}, "translation", to));
    EXPECT_TRUE(changes.apply(scene));
    return preview.applyChanges(scene, changes);
}

} // namespace wavelit::relight::testing
