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

// Writes the scene; when scene.lightingPath is set the lighting setup is referenced, not inlined
// (and is not written: save it with saveLightingSetup).
util::Status saveScene(const Scene& scene, const std::string& path);
util::Status saveLightingSetup(const LightingSetup& lighting, const std::string& path);

} // namespace wavelit::scene
