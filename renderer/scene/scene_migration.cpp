#include "scene/scene_migration.h"

#include <cmath>

namespace wavelit::scene {

using util::ErrorKind;

namespace {

void migrateEnvironmentV0(Json& env) {
    if (!env.is_object() || !env.contains("exposure") || !env["exposure"].is_number()) return;
    env["intensity"] = std::exp2(env["exposure"].get<double>());
    env.erase("exposure");
}

util::Status migrateV0(Json& doc, const std::string& file) {
    auto migrateLighting = [](Json& lighting) {
        if (lighting.is_object() && lighting.contains("environment")) migrateEnvironmentV0(lighting["environment"]);
    };
    if (doc["format"] == "wavelit-lighting") {
        migrateLighting(doc);
        return util::okStatus();
    }
    if (doc.contains("lighting")) migrateLighting(doc["lighting"]);
    if (!doc.contains("objects") || !doc["objects"].is_array()) return util::okStatus();
    for (size_t i = 0; i < doc["objects"].size(); ++i) {
        Json& obj = doc["objects"][i];
        if (!obj.is_object() || !obj.contains("material") || !obj["material"].is_string()) continue;
        const std::string name = obj["material"].get<std::string>();
        bool found = false;
        if (doc.contains("materials") && doc["materials"].is_array())
            for (const Json& m : doc["materials"])
                if (m.is_object() && m.value("name", std::string()) == name && m.contains("id")) {
                    obj["material"] = m["id"];
                    found = true;
                    break;
                }
        if (!found)
            return jsonError(ErrorKind::NotFound, {file, "/objects/" + std::to_string(i) + "/material"},
                             "material '" + name + "' not found");
    }
    return util::okStatus();
}

} // namespace

util::Status checkAndMigrate(Json& doc, const std::string& expectedFormat, int currentVersion,
                             const std::string& file) {
    if (!doc.is_object()) return jsonError(ErrorKind::Format, {file, ""}, "expected a JSON object at the top level");
    auto format = doc.find("format");
    if (format == doc.end()) return jsonError(ErrorKind::Format, {file, ""}, "missing \"format\": \"" + expectedFormat + "\"");
    if (!format->is_string() || *format != expectedFormat)
        return jsonError(ErrorKind::Format, {file, "/format"},
                         "expected \"" + expectedFormat + "\", got " + format->dump());
    auto version = doc.find("version");
    if (version == doc.end()) return jsonError(ErrorKind::Format, {file, ""}, "missing \"version\"");
    if (!version->is_number_integer())
        return jsonError(ErrorKind::Format, {file, "/version"}, std::string("expected an integer, got ") + jsonTypeName(*version));
    const int64_t v = version->get<int64_t>();
    if (v > currentVersion)
        return jsonError(ErrorKind::Unsupported, {file, "/version"},
                         "version " + std::to_string(v) + " is newer than this Wavelit reads (" +
                             std::to_string(currentVersion) + "); update Wavelit");
    if (v < 0) return jsonError(ErrorKind::Format, {file, "/version"}, "negative version " + std::to_string(v));
    if (v == 0)
        if (auto s = migrateV0(doc, file); !s) return s;
    doc["version"] = currentVersion;
    return util::okStatus();
}

} // namespace wavelit::scene
