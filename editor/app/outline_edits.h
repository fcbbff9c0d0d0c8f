// Outline edits (issue 14) as change sets: add a light of a type, an object from a loaded mesh, a
// material; delete or duplicate an entity; rename one. Pure functions of the scene snapshot — the
// document pushes the result as one undo step (SceneDocument::applyChanges), so every one of them
// is undoable and reaches the render thread as one scene::ChangeSet (an added light re-uploads the
// lights only; an added object rebuilds the BVH, architecture.md §5.B).
//
// Names stay unique per kind (scene validation requires it): an empty name becomes "<Type> N",
// a duplicate "<name> copy", "<name> copy 2", ...; a taken name is refused with a message.
#pragma once

#include "panels/entity_ref.h"

#include "scene/change_set.h"
#include "util/result.h"

#include <memory>
#include <optional>
#include <string>

namespace wavelit::editor {

// "point", "sphere", "rect", "spot", "sun" (the registry's light type names).
std::optional<scene::LightType> parseLightType(const std::string& text);

// A light of `type` with sensible defaults for a scene about a metre across: point/sphere/spot
// 3 m up, a rect overhead facing down, a sun from the upper left (3 W/m^2).
util::Result<scene::ChangeSet> addLightChange(const scene::Scene& scene, scene::LightType type,
                                              const std::string& name);
// An object from an already loaded mesh; `meshPath` as the file will store it (relative to the
// scene file). It uses the first material; a scene with none gets a default one in the same step.
util::Result<scene::ChangeSet> addObjectChange(const scene::Scene& scene, const std::string& meshPath,
                                               std::shared_ptr<const scene::TriangleMesh> mesh,
                                               const std::string& name);
util::Result<scene::ChangeSet> addMaterialChange(const scene::Scene& scene, const std::string& name);
// Deletes a light, an object or a material; a material some object uses is refused (naming the
// objects), as are the camera, the environment and the render settings.
util::Result<scene::ChangeSet> removeChange(const scene::Scene& scene, EntityRef ref);
// A copy with a new id and the name "<name> copy" (objects share the loaded mesh).
util::Result<scene::ChangeSet> duplicateChange(const scene::Scene& scene, EntityRef ref);
// The registry's "name" edit after checking the new name is free among entities of its kind.
util::Status checkRename(const scene::Scene& scene, EntityRef ref, const std::string& name);

// The id the first entity a change set adds gets (for selecting it afterwards); nullopt if none.
std::optional<EntityRef> addedEntity(const scene::ChangeSet& changes);

} // namespace wavelit::editor
