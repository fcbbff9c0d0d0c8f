#include "app/save_plan.h"

#include "scene/scene_io.h"

#include <filesystem>

namespace wavelit::editor {
namespace {

namespace fs = std::filesystem;

fs::path folderOf(const std::string& file) { return fs::absolute(fs::path(file)).parent_path(); }

// "<stem>.wllight" beside the scene, or "<stem>_lighting.wllight" where that is the setup being
// copied (a scene saved next to its own setup under the same stem).
fs::path copyFileFor(const std::string& scenePath, const std::string& sharedFile) {
    const fs::path scene = fs::absolute(fs::path(scenePath));
    fs::path copy = scene.parent_path() / (scene.stem().string() + ".wllight");
    if (copy.lexically_normal() == fs::path(sharedFile).lexically_normal())
        copy = scene.parent_path() / (scene.stem().string() + "_lighting.wllight");
    return copy;
}

} // namespace

std::string rebaseRelativePath(const std::string& path, const std::string& fromFolder,
                               const std::string& toFolder) {
    if (path.empty()) return path;
    const fs::path from = fs::absolute(fs::path(fromFolder)), to = fs::absolute(fs::path(toFolder));
    return (from / path).lexically_normal().lexically_relative(to.lexically_normal()).generic_string();
}

const char* lightingSaveName(LightingSave choice) {
    switch (choice) {
    case LightingSave::Reference: return "reference";
    case LightingSave::Copy: return "copy";
    case LightingSave::Inline: return "inline";
    case LightingSave::SaveSetup: return "setup";
    }
    return "?";
}

std::optional<LightingSave> parseLightingSave(const std::string& name) {
    for (LightingSave c : {LightingSave::Reference, LightingSave::Copy, LightingSave::Inline, LightingSave::SaveSetup})
        if (name == lightingSaveName(c)) return c;
    return std::nullopt;
}

std::string lightingFileOf(const scene::Scene& scene, const std::string& scenePath) {
    if (scene.lightingPath.empty()) return {};
    return (folderOf(scenePath) / scene.lightingPath).lexically_normal().string();
}

util::Result<SavePlan> planSave(const scene::Scene& scene, const std::string& fromPath,
                                const std::string& toPath, LightingSave choice, bool lightingEdited) {
    SavePlan plan;
    plan.scenePath = toPath;
    auto out = std::make_shared<scene::Scene>(scene);
    // Meshes, an inline map and the lighting reference, re-expressed for the new folder.
    if (!fromPath.empty()) scene::rebaseScenePaths(*out, fromPath, toPath);
    if (scene.lightingPath.empty()) {
        plan.scene = std::move(out);
        return plan;
    }
    const std::string shared = lightingFileOf(scene, fromPath.empty() ? toPath : fromPath);
    const fs::path sharedFolder = fs::path(shared).parent_path();
    switch (choice) {
    case LightingSave::Reference:
        if (lightingEdited)
            return util::makeError(util::ErrorKind::Invalid, toPath,
                                   "the lighting setup '" + shared +
                                       "' has unsaved edits: save it as a copy, inline, or into the setup");
        break;
    case LightingSave::SaveSetup:
        plan.lightingFile = shared;
        plan.lighting = out->lighting;
        break;
    case LightingSave::Copy: {
        const fs::path copy = copyFileFor(toPath, shared);
        out->lighting.environment.path = rebaseRelativePath(scene.lighting.environment.path,
                                                            sharedFolder.string(), copy.parent_path().string());
        out->lightingPath = copy.filename().string();
        plan.lightingFile = copy.string();
        plan.lighting = out->lighting;
        break;
    }
    case LightingSave::Inline:
        out->lighting.environment.path = rebaseRelativePath(scene.lighting.environment.path,
                                                            sharedFolder.string(), folderOf(toPath).string());
        out->lightingPath.clear();
        break;
    }
    plan.scene = std::move(out);
    return plan;
}

} // namespace wavelit::editor
