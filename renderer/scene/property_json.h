// JSON <-> entity through the property registry: the only place property values meet JSON, so
// no file format code names an individual property. Internal to the scene layer (nlohmann is a
// private dependency of wavelit_scene).
#pragma once

#include "scene/property_registry.h"
#include "util/result.h"

#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

namespace wavelit::scene {

// ordered_json keeps keys in declaration order, so saving twice gives identical bytes.
using Json = nlohmann::ordered_json;

// Where a JSON value sits, for messages: file name + JSON pointer ("/objects/2/material").
struct JsonPlace {
    std::string file;
    std::string where;
    JsonPlace child(const std::string& key) const { return {file, where + "/" + key}; }
    JsonPlace child(size_t index) const { return {file, where + "/" + std::to_string(index)}; }
};

util::Error jsonError(util::ErrorKind kind, const JsonPlace& at, const std::string& reason);
const char* jsonTypeName(const Json& value);

// Converts one JSON value to the property's type and checks range/options/paths.
util::Result<PropertyValue> valueFromJson(const Json& value, const PropertyInfo& info, const JsonPlace& at);
Json valueToJson(const PropertyValue& value);

// Reads the registry properties of `kind` from object `obj` into `entity`. Keys listed in
// `structural` (ids, nested sections) are the caller's. "extras" (an object) is stored as JSON text
// in *extras. Problems the file's author must fix but that do not stop the reading — an unknown
// key (with the closest known key when one is close), a key the entity's type does not use (a cone
// on a rect light), an option of a named kind the registry does not have (an unknown BRDF) — are
// appended to `problems`, one line each, so a load can list them
// all; any other bad value is returned as the error. Missing optional keys keep the entity's value.
util::Status readProperties(const Json& obj, EntityKind kind, void* entity, const JsonPlace& at,
                            const std::set<std::string>& structural, std::string* extras,
                            std::vector<std::string>& problems);

// Reads an "extras" value (which must be an object) as compact JSON text.
util::Status readExtras(const Json& value, const JsonPlace& at, std::string* extras);
// Writes `extras` back under "extras" when it is not empty.
void writeExtras(Json& obj, const std::string& extras);

// "unknown key 'roughnes' in /materials/0 (did you mean 'roughness'?)": the closest of `known` by
// edit distance is suggested when it is close enough to be a typo.
std::string unknownKeyProblem(const std::string& key, const JsonPlace& at, const std::vector<std::string>& known);

// Writes the applicable registry properties of `entity` into `obj` in declaration order.
void writeProperties(Json& obj, EntityKind kind, const void* entity);

// An entity list as a file stores it: per entity its "id", its registry properties and its extras.
template <class Entity>
Json writeEntityArray(const std::vector<Entity>& entities, EntityKind kind) {
    Json out = Json::array();
    for (const Entity& e : entities) {
        Json j = Json::object();
        j["id"] = e.id;
        writeProperties(j, kind, &e);
        writeExtras(j, e.extras);
        out.push_back(std::move(j));
    }
    return out;
}

} // namespace wavelit::scene
