// The edits file of `wavelit-cli relight --edits EDITS.json`: a JSON array of
// {"entity": …, "property": …, "value": …} with the property registry's names, as the editor's
// app.setProperty takes them (docs/scripting.md): entity "camera", "environment", "render",
// "kind:name" (material:ground, object:ring, light:sun) or a plain light/object/material name
// that only one entity has; object "material" values may be a material name. Edits are checked
// in order against the scene as the earlier ones left it, so every problem is found before
// anything is rendered; each error names the file and the edit (/2/value).
#pragma once

#include "scene/change_set.h"
#include "scene/scene.h"
#include "util/result.h"

#include <string>
#include <vector>

namespace wavelit::relight {

struct PlannedEdit {
    std::string entity;   // as written in the file
    std::string property;
    scene::ChangeSet changes; // against the scene after the previous edits
};

util::Result<std::vector<PlannedEdit>> readEditList(const std::string& path, const scene::Scene& scene);

// "camera" | "environment" | "render" | "kind:name" | a plain unique name.
util::Result<scene::EntityRef> resolveEntityName(const scene::Scene& scene, const std::string& text);

} // namespace wavelit::relight
