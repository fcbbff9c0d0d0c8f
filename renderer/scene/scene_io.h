// *.wlscene / *.wllight files (DESIGN.md §6): JSON with "format" and "version"; paths stored
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

struct LoadReport {
    std::vector<std::string> warnings; // recoverable problems (sanitised texels, unknown keys)
};

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
