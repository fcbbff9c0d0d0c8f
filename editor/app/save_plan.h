// SavePlan: which files a Save or Save As writes, and the scene as it will be written — pure path
// logic, no I/O, so every case is a unit test.
//
// A scene either holds its lighting inline or refers to a *.wllight (Scene::lightingPath,
// relative to the scene file; the setup's environment map is relative to the *.wllight). Edits of
// referenced lighting are part of the open document; where they go is the artist's choice:
//   Reference  keep referring to the same setup file (only while the lighting is unedited);
//   Copy       write the edited setup beside the new scene ("<scene>.wllight") and refer to it —
//              Save As's default for edited lighting: a setup other scenes share is never rewritten;
//   Inline     write the lighting into the scene file;
//   SaveSetup  rewrite the referenced setup file itself ("save lighting setup"): what Save does.
// All relative paths (meshes, the lighting reference, environment maps) are re-expressed for the
// files' new folders.
#pragma once

#include "scene/scene.h"
#include "util/result.h"

#include <memory>
#include <optional>
#include <string>

namespace wavelit::editor {

enum class LightingSave { Reference, Copy, Inline, SaveSetup };

const char* lightingSaveName(LightingSave choice); // "reference", "copy", "inline", "setup"
std::optional<LightingSave> parseLightingSave(const std::string& name);

struct SavePlan {
    std::string scenePath;                       // the scene file to write
    std::shared_ptr<const scene::Scene> scene;   // as written: paths relative to scenePath
    std::string lightingFile;                    // the *.wllight to write; empty: none
    std::optional<scene::LightingSetup> lighting; // its content (map relative to lightingFile)
};

// `fromPath`: where the document's relative paths start (its current file). `lightingEdited`:
// the referenced setup differs from its file. Reference with edited lighting is refused (the edits
// would be lost); for inline lighting the choice does not matter.
util::Result<SavePlan> planSave(const scene::Scene& scene, const std::string& fromPath,
                                const std::string& toPath, LightingSave choice, bool lightingEdited);

// `path`, relative to `fromFolder`, re-expressed relative to `toFolder` ("" stays "").
std::string rebaseRelativePath(const std::string& path, const std::string& fromFolder,
                               const std::string& toFolder);

// The absolute file a referenced setup lives in ("" for inline lighting).
std::string lightingFileOf(const scene::Scene& scene, const std::string& scenePath);

} // namespace wavelit::editor
