// *.wlscene / *.wllight reading and writing. Every property goes through the registry
// (property_json.h); this file only knows the document's sections, ids and file references.
//
// Problems the author must fix but that do not stop the reading (unknown keys, unknown BRDFs:
// property_json.h) are collected per file; a file with any fails to load with one error that names
// the file and lists them all, one per line, so the editor, `render` and `validate` show the same.
//
// Lighting references: a scene's "lighting" is either an inline setup or a path to a *.wllight,
// or to another *.wlscene whose lighting is borrowed (so a shot can share a look with another);
// such chains are followed with cycle detection. The loaded setup's environment path is always
// relative to the file Scene::lightingPath names, which is where saveLightingSetup would put it.
#include "scene/scene_io.h"

#include "scene/atomic_file.h"
#include "scene/image_io.h"
#include "scene/load_guard.h"
#include "scene/mesh_loader.h"
#include "scene/property_json.h"
#include "scene/scene_migration.h"
#include "scene/scene_validation.h"
#include "util/path_util.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace wavelit::scene {

namespace fs = std::filesystem;
using util::ErrorKind;
using util::makeError;

namespace {

const std::vector<std::string> kSceneKeys = {"format", "version", "name", "camera", "render",
                                             "materials", "objects", "lighting", "extras"};
const std::vector<std::string> kLightingKeys = {"format", "version", "name", "environment", "lights", "extras"};
// An inline "lighting" object: a *.wllight body without format and version.
const std::vector<std::string> kInlineLightingKeys = {"name", "environment", "lights", "extras"};

// The collected problems of `file` (and `hard`, the error that stopped the reading, if any) as one
// error: "f.wlscene: <problem>" for one, "f.wlscene: N problems:\n  <problem>\n  ..." for more.
util::Error problemsError(const std::string& file, std::vector<std::string> problems,
                          const util::Error* hard) {
    if (hard) problems.push_back(hard->file == file ? util::Error{hard->kind, "", hard->where, hard->reason}.message()
                                                    : hard->message());
    std::string reason;
    if (problems.size() == 1) {
        reason = problems[0];
    } else {
        reason = std::to_string(problems.size()) + " problems:";
        for (const std::string& p : problems) reason += "\n  " + p;
    }
    return makeError(ErrorKind::Invalid, file, reason);
}

// Runs `read` (which appends problems to the vector it is given) for the document `file`; when it
// collected any, the result is problemsError.
template <typename T, typename Read>
util::Result<T> collectProblems(const std::string& file, Read&& read) {
    std::vector<std::string> problems;
    util::Result<T> result = read(problems);
    if (problems.empty()) return result;
    return problemsError(file, std::move(problems), result ? nullptr : &result.error());
}

// Unknown keys of a document root or inline lighting object (entities: readProperties).
void checkKeys(const Json& obj, const std::vector<std::string>& known, const JsonPlace& at,
               std::vector<std::string>& problems) {
    for (auto it = obj.begin(); it != obj.end(); ++it)
        if (std::find(known.begin(), known.end(), it.key()) == known.end())
            problems.push_back(unknownKeyProblem(it.key(), at, known));
}

util::Status readRootExtras(const Json& obj, const JsonPlace& at, std::string* extras) {
    auto it = obj.find("extras");
    return it == obj.end() ? util::okStatus() : readExtras(*it, at.child("extras"), extras);
}

// " at line N" for the overflowing literal quoted in nlohmann's "number overflow parsing '1e999'"
// (its first occurrence in the text), so a hand-edited file says where to look.
std::string numberOverflowPlace(const std::string& text, const std::string& reason) {
    const size_t open = reason.find('\''), close = reason.rfind('\'');
    if (open == std::string::npos || close <= open + 1) return {};
    const size_t at = text.find(reason.substr(open + 1, close - open - 1));
    if (at == std::string::npos) return {};
    return " at line " + std::to_string(1 + std::count(text.begin(), text.begin() + ptrdiff_t(at), '\n'));
}

// Deepest nesting of arrays and objects a document may have. Wavelit's own need 4 levels, "extras"
// of other tools a few more; nlohmann's dump and copies recurse once per level, so a 100000-deep
// "extras" overflowed the stack (segfault in `validate`) and is refused before parsing.
constexpr int kMaxJsonDepth = 256;

// The 1-based line where `text` first nests deeper than kMaxJsonDepth, or 0. Brackets inside
// strings do not count.
size_t lineTooDeep(const std::string& text) {
    int depth = 0;
    size_t line = 1;
    bool inString = false, escaped = false;
    for (const char c : text) {
        if (c == '\n') ++line;
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) return line;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return 0;
}

util::Result<Json> readJsonFile(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return makeError(ErrorKind::NotFound, path, "no such file");
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) return makeError(ErrorKind::Io, path, "cannot read file");
    const std::string bytes = text.str();
    if (const size_t line = lineTooDeep(bytes))
        return makeError(ErrorKind::Format, path, "invalid JSON: nested deeper than " + std::to_string(kMaxJsonDepth) +
                                                      " levels at line " + std::to_string(line));
    try {
        return Json::parse(bytes);
    } catch (const Json::exception& e) {
        // e.what() is "[json.exception.parse_error.101] parse error at line 3, column 5: ..." or,
        // for a number no double holds (1e999), "[json.exception.out_of_range.406] number
        // overflow parsing '1e999'", which has no place: the line of the literal is added.
        std::string reason = e.what();
        if (auto p = reason.find("] "); p != std::string::npos) reason = reason.substr(p + 2);
        if (e.id == 406) reason += numberOverflowPlace(bytes, reason);
        return makeError(ErrorKind::Format, path, "invalid JSON: " + reason);
    }
}

fs::path folderOf(const std::string& file) {
    fs::path dir = fs::path(file).parent_path();
    return dir.empty() ? fs::path(".") : dir;
}

// `file` as a portable relative path from `folder` (absolute paths are never stored).
std::string relativeTo(const std::string& file, const fs::path& folder) {
    return fs::absolute(file).lexically_normal().lexically_relative(fs::absolute(folder).lexically_normal()).generic_string();
}

using util::lowerExtension;

util::Result<std::string> readName(const Json& doc, const JsonPlace& at) {
    auto it = doc.find("name");
    if (it == doc.end()) return std::string();
    if (!it->is_string()) return jsonError(ErrorKind::Format, at.child("name"), std::string("name: expected a string, got ") + jsonTypeName(*it));
    return it->get<std::string>();
}

// Reads an array of entities with ids; a missing id is assigned after the largest one in use.
template <typename E>
util::Status readEntities(const Json& doc, const std::string& key, EntityKind kind, std::vector<E>& out,
                          const JsonPlace& at, std::vector<std::string>& problems) {
    auto it = doc.find(key);
    if (it == doc.end()) return util::okStatus();
    if (!it->is_array()) return jsonError(ErrorKind::Format, at.child(key), key + ": expected an array, got " + jsonTypeName(*it));
    std::vector<size_t> unnumbered;
    for (size_t i = 0; i < it->size(); ++i) {
        const Json& item = (*it)[i];
        const JsonPlace here = at.child(key).child(i);
        E entity;
        if (auto s = readProperties(item, kind, &entity, here, {"id"}, &entity.extras, problems); !s) return s;
        if (auto id = item.find("id"); id != item.end()) {
            if (!id->is_number_unsigned() || id->get<uint64_t>() == kInvalidId)
                return jsonError(ErrorKind::Format, here.child("id"), std::string("id: expected a positive integer, got ") + jsonTypeName(*id));
            entity.id = id->get<uint64_t>();
        } else {
            unnumbered.push_back(out.size());
        }
        out.push_back(std::move(entity));
    }
    EntityId next = 1;
    for (const E& e : out) next = std::max(next, e.id + 1);
    for (size_t i : unnumbered) out[i].id = next++;
    return util::okStatus();
}

// The body of a lighting setup: a *.wllight document or a scene's inline "lighting" object.
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
    Json lights = Json::array();
    for (const Light& l : lighting.lights) {
        Json j = Json::object();
        j["id"] = l.id;
        writeProperties(j, EntityKind::Light, &l);
        writeExtras(j, l.extras);
        lights.push_back(j);
    }
    out["lights"] = lights;
    writeExtras(out, lighting.extras);
    return out;
}

// Loads the lighting setup `file` defines or borrows; its environment path is made relative to
// `file`'s folder. `chain` holds the files already on the way here (cycle detection), starting
// with the scene being loaded, `rootFile` as the user named it.
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
    const std::string ext = lowerExtension(file);
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

util::Status loadEnvironment(Environment& env, const fs::path& base, const std::string& referrer,
                             const std::string& where, LoadReport* report) {
    if (env.path.empty() || env.image) return util::okStatus();
    auto image = loadImage((base / env.path).lexically_normal().string());
    if (!image) return makeError(image.error().kind, referrer, image.error().message(), where);
    if (report) report->warnings.insert(report->warnings.end(), image->warnings.begin(), image->warnings.end());
    env.image = std::make_shared<const util::ImageRGB>(std::move(image->image));
    return util::okStatus();
}

// An error found in a file the scene references is reported from the scene, so the message names
// both: "a.wlscene:/lighting: studio.wllight:/environment/map: ...".
util::Error fromScene(const util::Error& e, const std::string& scenePath, const std::string& where) {
    if (e.file == scenePath) return e;
    return makeError(e.kind, scenePath, e.message(), where);
}

util::Status writeJson(const Json& doc, const std::string& path) {
    return writeFileAtomic(path, doc.dump(2) + "\n");
}

} // namespace

util::Status loadAssets(Scene& scene, const std::string& scenePath, LoadReport* report) {
    const fs::path base = folderOf(scenePath);
    std::map<std::string, std::shared_ptr<const TriangleMesh>> cache;
    for (const Object& o : scene.objects)
        if (o.mesh) cache.emplace(o.meshPath, o.mesh);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        Object& o = scene.objects[i];
        if (o.mesh) continue;
        if (auto it = cache.find(o.meshPath); it != cache.end()) {
            o.mesh = it->second;
            continue;
        }
        auto mesh = loadMesh((base / o.meshPath).lexically_normal().string(), report ? &report->warnings : nullptr);
        if (!mesh) return makeError(mesh.error().kind, scenePath, mesh.error().message(), "/objects/" + std::to_string(i) + "/mesh");
        o.mesh = std::make_shared<const TriangleMesh>(std::move(mesh).value());
        cache.emplace(o.meshPath, o.mesh);
    }
    if (scene.lightingPath.empty())
        return loadEnvironment(scene.lighting.environment, base, scenePath, "/lighting/environment/map", report);
    const fs::path lightingFile = (base / scene.lightingPath).lexically_normal();
    return loadEnvironment(scene.lighting.environment, folderOf(lightingFile.string()), lightingFile.string(),
                           "/environment/map", report);
}

namespace {

util::Result<Scene> loadSceneUnguarded(const std::string& path, LoadReport* report) {
    auto doc = readJsonFile(path);
    if (!doc) return doc.error();
    if (auto s = checkAndMigrate(*doc, "wavelit-scene", kSceneFormatVersion, path); !s) return s.error();
    auto read = collectProblems<Scene>(path, [&](std::vector<std::string>& problems) -> util::Result<Scene> {
        const JsonPlace root{path, ""};
        Scene scene;
        checkKeys(*doc, kSceneKeys, root, problems);
        if (auto s = readRootExtras(*doc, root, &scene.extras); !s) return s.error();
        auto name = readName(*doc, root);
        if (!name) return name.error();
        scene.name = *name;
        if (auto it = doc->find("camera"); it != doc->end())
            if (auto s = readProperties(*it, EntityKind::Camera, &scene.camera, root.child("camera"), {},
                                        &scene.camera.extras, problems);
                !s)
                return s.error();
        if (auto it = doc->find("render"); it != doc->end())
            if (auto s = readProperties(*it, EntityKind::Render, &scene.render, root.child("render"), {},
                                        &scene.render.extras, problems);
                !s)
                return s.error();
        if (auto s = readEntities(*doc, "materials", EntityKind::Material, scene.materials, root, problems); !s) return s.error();
        if (auto s = readEntities(*doc, "objects", EntityKind::Object, scene.objects, root, problems); !s) return s.error();
        if (auto it = doc->find("lighting"); it != doc->end()) {
            if (it->is_string()) {
                scene.lightingPath = it->get<std::string>();
                if (!isPortableRelativePath(scene.lightingPath))
                    return makeError(ErrorKind::Invalid, path, "absolute path '" + scene.lightingPath + "' not allowed: paths are relative to the file", "/lighting");
                auto lighting = lightingFromFile(folderOf(path) / scene.lightingPath, {fs::weakly_canonical(path)}, path);
                if (!lighting) return fromScene(lighting.error(), path, "/lighting");
                scene.lighting = std::move(lighting).value();
            } else {
                auto lighting = readLightingBody(*it, root.child("lighting"), false, problems);
                if (!lighting) return lighting.error();
                scene.lighting = std::move(lighting).value();
            }
        }
        return scene;
    });
    if (!read) return read.error();
    Scene scene = std::move(read).value();
    if (auto s = validateScene(scene, path); !s) return s.error();
    if (auto s = loadAssets(scene, path, report); !s) return fromScene(s.error(), path, "/lighting");
    return scene;
}

util::Result<LightingSetup> loadLightingSetupUnguarded(const std::string& path, LoadReport* report) {
    auto doc = readJsonFile(path);
    if (!doc) return doc.error();
    if (auto s = checkAndMigrate(*doc, "wavelit-lighting", kLightingFormatVersion, path); !s) return s.error();
    auto lighting = collectProblems<LightingSetup>(path, [&](std::vector<std::string>& problems) {
        return readLightingBody(*doc, {path, ""}, true, problems);
    });
    if (!lighting) return lighting;
    if (auto s = loadEnvironment(lighting->environment, folderOf(path), path, "/environment/map", report); !s) return s.error();
    return lighting;
}

} // namespace

util::Result<Scene> loadScene(const std::string& path, LoadReport* report) {
    return guardLoad<Scene>(path, [&] { return loadSceneUnguarded(path, report); });
}

util::Result<LightingSetup> loadLightingSetup(const std::string& path, LoadReport* report) {
    return guardLoad<LightingSetup>(path, [&] { return loadLightingSetupUnguarded(path, report); });
}

util::Status saveScene(const Scene& scene, const std::string& path) {
    Json doc = Json::object();
    doc["format"] = "wavelit-scene";
    doc["version"] = kSceneFormatVersion;
    doc["name"] = scene.name;
    writeExtras(doc, scene.extras);
    Json camera = Json::object(), render = Json::object();
    writeProperties(camera, EntityKind::Camera, &scene.camera);
    writeProperties(render, EntityKind::Render, &scene.render);
    writeExtras(camera, scene.camera.extras);
    writeExtras(render, scene.render.extras);
    doc["camera"] = camera;
    doc["render"] = render;
    Json materials = Json::array(), objects = Json::array();
    for (const Material& m : scene.materials) {
        Json j = Json::object();
        j["id"] = m.id;
        writeProperties(j, EntityKind::Material, &m);
        writeExtras(j, m.extras);
        materials.push_back(j);
    }
    for (const Object& o : scene.objects) {
        Json j = Json::object();
        j["id"] = o.id;
        writeProperties(j, EntityKind::Object, &o);
        writeExtras(j, o.extras);
        objects.push_back(j);
    }
    doc["materials"] = materials;
    doc["objects"] = objects;
    doc["lighting"] = scene.lightingPath.empty() ? writeLightingBody(scene.lighting) : Json(scene.lightingPath);
    return writeJson(doc, path);
}

util::Status saveLightingSetup(const LightingSetup& lighting, const std::string& path) {
    Json doc = Json::object();
    doc["format"] = "wavelit-lighting";
    doc["version"] = kLightingFormatVersion;
    const Json body = writeLightingBody(lighting);
    for (auto it = body.begin(); it != body.end(); ++it) doc[it.key()] = it.value();
    return writeJson(doc, path);
}

util::Status attachLightingSetup(Scene& scene, const std::string& scenePath, const std::string& lightingFile,
                                 LoadReport* report) {
    auto lighting = loadLightingSetup(lightingFile, report);
    if (!lighting) return lighting.error();
    scene.lighting = std::move(lighting).value();
    scene.lightingPath = relativeTo(lightingFile, folderOf(scenePath));
    return util::okStatus();
}

void rebaseScenePaths(Scene& scene, const std::string& fromScenePath, const std::string& toScenePath) {
    const fs::path from = folderOf(fromScenePath), to = folderOf(toScenePath);
    auto rebase = [&](std::string& p) {
        if (!p.empty()) p = relativeTo((from / p).string(), to);
    };
    for (Object& o : scene.objects) rebase(o.meshPath);
    if (scene.lightingPath.empty())
        rebase(scene.lighting.environment.path);
    else
        rebase(scene.lightingPath); // the setup's own map stays relative to its *.wllight
}

} // namespace wavelit::scene
