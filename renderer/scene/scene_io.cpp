// *.wlscene / *.wllight reading and writing: the scene's sections, the load and save entry points,
// assets and paths. Every property goes through the registry (property_json.h); the pieces are
// scene_io_json.h (the JSON text), scene_io_read.h (problems, names, entity arrays),
// scene_io_lighting.h (lighting bodies and references) and scene_io_paths.h.
#include "scene/scene_io.h"

#include "scene/environment_mask.h"
#include "scene/image_io.h"
#include "scene/load_guard.h"
#include "scene/mesh_loader.h"
#include "scene/property_json.h"
#include "scene/scene_io_json.h"
#include "scene/scene_io_lighting.h"
#include "scene/scene_io_paths.h"
#include "scene/scene_io_read.h"
#include "scene/scene_migration.h"
#include "scene/scene_validation.h"
#include "plugins/brdf_table.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <map>

namespace wavelit::scene {

namespace fs = std::filesystem;
using util::ErrorKind;
using util::makeError;

namespace {

const std::vector<std::string> kSceneKeys = {"format", "version", "name", "camera", "render",
                                             "materials", "objects", "lighting", "extras"};

// An extracted sun's mask (docs/lightmix.md) needs a map to mask and a direction to point at.
util::Status checkEnvironmentMask(const Environment& env, const std::string& referrer, const std::string& mapWhere) {
    if (!hasEnvironmentMask(env)) return util::okStatus();
    const std::string where = mapWhere.substr(0, mapWhere.rfind('/'));
    if (env.path.empty())
        return makeError(ErrorKind::Invalid, referrer,
                         "the environment has a mask (maskRadius " + std::to_string(env.maskRadiusDeg) +
                             " deg) but no map to mask; remove maskRadius or name a map",
                         where + "/maskRadius");
    const glm::vec3 d = env.maskDirection;
    if (!(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z)) || glm::dot(d, d) < 1e-12f)
        return makeError(ErrorKind::Invalid, referrer,
                         "the environment's maskDirection must be a non-zero direction (the centre of the masked cap)",
                         where + "/maskDirection");
    return util::okStatus();
}

util::Status loadEnvironment(Environment& env, const fs::path& base, const std::string& referrer,
                             const std::string& where, LoadReport* report) {
    if (auto s = checkEnvironmentMask(env, referrer, where); !s) return s;
    if (env.path.empty() || env.image) return util::okStatus();
    auto image = loadImage((base / env.path).lexically_normal().string());
    if (!image) return makeError(image.error().kind, referrer, image.error().message(), where);
    if (report) report->warnings.insert(report->warnings.end(), image->warnings.begin(), image->warnings.end());
    env.image = std::make_shared<const util::ImageRGB>(hasEnvironmentMask(env) ? applyEnvironmentMask(image->image, env)
                                                                              : std::move(image->image));
    return util::okStatus();
}

// An error found in a file the scene references is reported from the scene, so the message names
// both: "a.wlscene:/lighting: studio.wllight:/environment/map: ...".
util::Error fromScene(const util::Error& e, const std::string& scenePath, const std::string& where) {
    if (e.file == scenePath) return e;
    return makeError(e.kind, scenePath, e.message(), where);
}

// The tables of materials whose plugin reads a data file, each file once (materials may share
// one). A table loaded from another file than the material now names (an edited brdfFile) is
// replaced.
util::Status loadBrdfTables(Scene& scene, const fs::path& base, const std::string& scenePath) {
    std::map<std::string, std::shared_ptr<const plugins::BrdfTable>> cache; // by resolved path
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        Material& m = scene.materials[i];
        const plugins::Brdf* brdf = plugins::findBrdf(m.brdf);
        if (!brdf || !plugins::brdfReadsFile(*brdf)) continue;
        const std::string where = "/materials/" + std::to_string(i) + "/brdfFile";
        if (m.brdfFile.empty())
            return makeError(util::ErrorKind::Invalid, scenePath,
                             "material '" + m.name + "' uses the " + m.brdf + " BRDF but names no brdfFile", where);
        const std::string path = (base / m.brdfFile).lexically_normal().string();
        if (m.brdfTable && m.brdfTable->file == path) continue;
        if (auto it = cache.find(path); it != cache.end()) {
            m.brdfTable = it->second;
            continue;
        }
        auto table = plugins::loadMerlBrdf(path);
        if (!table) return makeError(table.error().kind, scenePath, table.error().message(), where);
        m.brdfTable = *table;
        cache.emplace(path, m.brdfTable);
    }
    return util::okStatus();
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
    if (auto s = loadBrdfTables(scene, base, scenePath); !s) return s;
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
    doc["materials"] = writeEntityArray(scene.materials, EntityKind::Material);
    doc["objects"] = writeEntityArray(scene.objects, EntityKind::Object);
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
    for (Material& m : scene.materials) rebase(m.brdfFile);
    if (scene.lightingPath.empty())
        rebase(scene.lighting.environment.path);
    else
        rebase(scene.lightingPath); // the setup's own map stays relative to its *.wllight
}

} // namespace wavelit::scene
