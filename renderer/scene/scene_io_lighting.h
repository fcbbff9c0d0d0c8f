// Lighting setups in scene_io's documents: the body a *.wllight holds and a scene inlines, and the
// chains of references a scene's "lighting" may name. Internal to the scene layer.
//
// Lighting references: a scene's "lighting" is either an inline setup or a path to a *.wllight,
// or to another *.wlscene whose lighting is borrowed (so a shot can share a look with another);
// such chains are followed with cycle detection. The loaded setup's environment path is always
// relative to the file Scene::lightingPath names, which is where saveLightingSetup would put it.
#pragma once

#include "scene/property_json.h"
#include "scene/scene.h"
#include "util/result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace wavelit::scene {

// The body of a lighting setup: a *.wllight document (topLevel) or a scene's inline "lighting"
// object (no format and version). Unknown keys are appended to `problems`; the setup's own checks
// (validateLighting) run only on a read without problems, as a typo'd key might be their cause.
util::Result<LightingSetup> readLightingBody(const Json& obj, const JsonPlace& at, bool topLevel,
                                             std::vector<std::string>& problems);
Json writeLightingBody(const LightingSetup& lighting);

// Loads the lighting setup `file` defines or borrows; its environment path is made relative to
// `file`'s folder. `chain` holds the files already on the way here (cycle detection), starting
// with the scene being loaded, `rootFile` as the user named it.
util::Result<LightingSetup> lightingFromFile(const std::filesystem::path& file, std::vector<std::filesystem::path> chain,
                                             const std::string& rootFile);

} // namespace wavelit::scene
