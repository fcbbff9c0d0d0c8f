// What the scene and lighting readers of scene_io share: collecting a file's problems into one
// error, unknown root keys, the "name" and "extras" of a root, and arrays of entities with ids.
// Internal to the scene layer.
//
// Problems the author must fix but that do not stop the reading (unknown keys, unknown BRDFs:
// property_json.h) are collected per file; a file with any fails to load with one error that names
// the file and lists them all, one per line, so the editor, `render` and `validate` show the same.
#pragma once

#include "scene/property_json.h"
#include "scene/scene.h"
#include "util/result.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace wavelit::scene {

// The collected problems of `file` (and `hard`, the error that stopped the reading, if any) as one
// error: "f.wlscene: <problem>" for one, "f.wlscene: N problems:\n  <problem>\n  ..." for more.
util::Error problemsError(const std::string& file, std::vector<std::string> problems, const util::Error* hard);

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
               std::vector<std::string>& problems);

util::Status readRootExtras(const Json& obj, const JsonPlace& at, std::string* extras);

util::Result<std::string> readName(const Json& doc, const JsonPlace& at);

// Reads an array of entities with ids; a missing id is assigned after the largest one in use.
template <typename E>
util::Status readEntities(const Json& doc, const std::string& key, EntityKind kind, std::vector<E>& out,
                          const JsonPlace& at, std::vector<std::string>& problems) {
    using util::ErrorKind;
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

} // namespace wavelit::scene
