// The JSON text of *.wlscene / *.wllight files for scene_io: reading that turns every way a text
// can fail to parse (syntax, a number no double holds, nesting that would overflow the stack) into
// a load error naming the file and line, and atomic writing. Internal to the scene layer.
#pragma once

#include "scene/property_json.h"
#include "util/result.h"

#include <string>

namespace wavelit::scene {

// Deepest nesting of arrays and objects a document may have. Wavelit's own need 4 levels, "extras"
// of other tools a few more; nlohmann's dump and copies recurse once per level, so a 100000-deep
// "extras" overflowed the stack (segfault in `validate`) and is refused before parsing.
inline constexpr int kMaxJsonDepth = 256;

util::Result<Json> readJsonFile(const std::string& path);
// Two-space indented, newline-terminated, written atomically (atomic_file.h).
util::Status writeJson(const Json& doc, const std::string& path);

} // namespace wavelit::scene
