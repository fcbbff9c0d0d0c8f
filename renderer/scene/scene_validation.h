// Whole-model checks the per-property ranges of the registry cannot express: unique ids and names
// per entity kind, references that resolve, and relations between properties (a spot's inner cone
// inside its outer one, a camera not looking at its own position). Errors carry the JSON path of
// the offending entity so a message points into the file.
#pragma once

#include "scene/scene.h"
#include "util/result.h"

#include <string>

namespace wavelit::scene {

// `prefix` is the JSON path of the lighting section: "" in a *.wllight, "/lighting" inline.
util::Status validateLighting(const LightingSetup& lighting, const std::string& file, const std::string& prefix);
util::Status validateScene(const Scene& scene, const std::string& file);

} // namespace wavelit::scene
