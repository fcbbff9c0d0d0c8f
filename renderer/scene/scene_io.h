// *.wlscene / *.wllight files (architecture.md §6): JSON with "format" and "version"; paths stored
// relative to the file that names them; older versions migrated, newer ones rejected with a
// clear error. Loading also loads the meshes (Assimp) and the environment image (OpenEXR/.hdr)
// so a loaded Scene is ready to render. Saves are atomic (see atomic_file.h).
#pragma once

#include "scene/scene.h"
#include "util/result.h"

#include <string>
#include <vector>

namespace wavelit::scene {

inline constexpr int kSceneFormatVersion = 1;
inline constexpr int kLightingFormatVersion = 1;

// Repairs that loading made (NaN/Inf/negative texels replaced or clamped, zero-area triangles
// skipped): the file loads, and the callers show these (`validate` fails on them).
struct LoadReport {
    std::vector<std::string> warnings;
};

// A file that does not mean what it says fails to load. Unknown keys (with a "did you mean" when a
// known key is close) and materials naming a BRDF that no plugin provides (plugins::brdfNames())
// are all collected, and the error names the file and lists them, one per line:
//   "a.wlscene: unknown key 'roughnes' in /materials/0 (did you mean 'roughness'?)"           (one)
//   "a.wlscene: 2 problems:\n  unknown key ...\n  material 'ground' (/materials/1/brdf): unknown
//    BRDF 'phong'; known: lambert, ggx"                                                       (more)
// A problem in a referenced *.wllight is reported from the scene: "a.wlscene:/lighting: l.wllight: ...".
// Any other bad value stops the reading at once with its own error (after the collected ones, if
// any). Keys under "extras" are kept in the model's `extras` and written back by the savers.
util::Result<Scene> loadScene(const std::string& path, LoadReport* report = nullptr);
util::Result<LightingSetup> loadLightingSetup(const std::string& path, LoadReport* report = nullptr);

// Loads every mesh and the environment image that is not loaded yet — after a load, or after an
// edit changed a mesh or map path (the registry's setter drops the stale asset). Meshes used by
// several objects are loaded once. scenePath: the scene file the relative paths start from.
util::Status loadAssets(Scene& scene, const std::string& scenePath, LoadReport* report = nullptr);

// Writes the scene; when scene.lightingPath is set the lighting setup is referenced, not inlined
// (and is not written: save it with saveLightingSetup).
util::Status saveScene(const Scene& scene, const std::string& path);
util::Status saveLightingSetup(const LightingSetup& lighting, const std::string& path);

// Puts the lighting setup of `lightingFile` (*.wllight) onto the scene as a reference: the setup is
// loaded (with its environment image) and scene.lightingPath becomes lightingFile relative to the
// scene file's folder. On failure the scene is unchanged.
util::Status attachLightingSetup(Scene& scene, const std::string& scenePath, const std::string& lightingFile,
                                 LoadReport* report = nullptr);

// "Save as" into another folder: rewrites the scene's relative paths (meshes, lighting reference,
// an inline environment map) so they name the same files from `toScenePath`'s folder.
void rebaseScenePaths(Scene& scene, const std::string& fromScenePath, const std::string& toScenePath);

} // namespace wavelit::scene
