// Reading and writing lighting setups and following lighting references (see scene_io_lighting.h).
#include "scene/scene_io_lighting.h"

#include "scene/scene_io.h"
#include "scene/scene_io_json.h"
#include "scene/scene_io_paths.h"
#include "scene/scene_io_read.h"
#include "scene/scene_migration.h"
#include "scene/scene_validation.h"
#include "util/path_util.h"

namespace wavelit::scene {

namespace fs = std::filesystem;
using util::ErrorKind;
using util::makeError;

namespace {

const std::vector<std::string> kLightingKeys = {"format", "version", "name", "environment", "lights", "extras"};
// An inline "lighting" object: a *.wllight body without format and version.
const std::vector<std::string> kInlineLightingKeys = {"name", "environment", "lights", "extras"};

} // namespace

util::Result<LightingSetup> readLightingBody(const Json& obj, const JsonPlace& at, bool topLevel,
                                             std::vector<std::string>& problems) {
    if (!obj.is_object()) return jsonError(ErrorKind::Format, at, std::string("lighting: expected an object, got ") + jsonTypeName(obj));
    LightingSetup lighting;
    auto name = readName(obj, at);
    if (!name) return name.error();
    lighting.name = *name;
    checkKeys(obj, topLevel ? kLightingKeys : kInlineLightingKeys, at, problems);
    if (auto s = readRootExtras(obj, at, &lighting.extras); !s) return s.error();
    if (auto env = obj.find("environment"); env != obj.end())
        if (auto s = readProperties(*env, EntityKind::Environment, &lighting.environment, at.child("environment"), {},
                                    &lighting.environment.extras, problems);
            !s)
            return s.error();
    if (auto s = readEntities(obj, "lights", EntityKind::Light, lighting.lights, at, problems); !s) return s.error();
    // Checks of the whole setup wait for a clean read: a typo'd key might be their cause.
    if (!problems.empty()) return lighting;
    if (auto s = validateLighting(lighting, at.file, at.where); !s) return s.error();
    return lighting;
}

Json writeLightingBody(const LightingSetup& lighting) {
    Json out = Json::object();
    out["name"] = lighting.name;
    Json env = Json::object();
    writeProperties(env, EntityKind::Environment, &lighting.environment);
    writeExtras(env, lighting.environment.extras);
    out["environment"] = env;
    out["lights"] = writeEntityArray(lighting.lights, EntityKind::Light);
    writeExtras(out, lighting.extras);
    return out;
}

util::Result<LightingSetup> lightingFromFile(const fs::path& file, std::vector<fs::path> chain,
                                             const std::string& rootFile) {
    const fs::path key = fs::weakly_canonical(file);
    for (const fs::path& seen : chain)
        if (seen == key) {
            std::string loop;
            for (const fs::path& p : chain) loop += p.filename().string() + " -> ";
            return makeError(ErrorKind::Invalid, rootFile, "cyclic lighting reference: " + loop + file.filename().string(), "/lighting");
        }
    chain.push_back(key);
    auto doc = readJsonFile(file.string());
    if (!doc) return doc.error();
    const std::string ext = util::lowerExtension(file);
    if (ext == ".wllight") {
        if (auto s = checkAndMigrate(*doc, "wavelit-lighting", kLightingFormatVersion, file.string()); !s) return s.error();
        return collectProblems<LightingSetup>(file.string(), [&](std::vector<std::string>& problems) {
            return readLightingBody(*doc, {file.string(), ""}, true, problems);
        });
    }
    if (ext != ".wlscene") return makeError(ErrorKind::Unsupported, file.string(), "a lighting reference must name a .wllight or .wlscene file");
    if (auto s = checkAndMigrate(*doc, "wavelit-scene", kSceneFormatVersion, file.string()); !s) return s.error();
    auto ref = doc->find("lighting");
    if (ref == doc->end()) return LightingSetup{};
    if (!ref->is_string())
        return collectProblems<LightingSetup>(file.string(), [&](std::vector<std::string>& problems) {
            return readLightingBody(*ref, {file.string(), "/lighting"}, false, problems);
        });
    const std::string target = ref->get<std::string>();
    if (!isPortableRelativePath(target))
        return makeError(ErrorKind::Invalid, file.string(), "absolute path '" + target + "' not allowed: paths are relative to the file", "/lighting");
    const fs::path next = folderOf(file.string()) / target;
    auto lighting = lightingFromFile(next, chain, rootFile);
    if (!lighting) return lighting;
    std::string& env = lighting->environment.path;
    if (!env.empty())
        env = (folderOf(next.string()) / env).lexically_normal().lexically_relative(folderOf(file.string())).generic_string();
    return lighting;
}

} // namespace wavelit::scene
