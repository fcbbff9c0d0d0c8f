// Reading and writing the JSON text of scene_io's documents (see scene_io_json.h).
#include "scene/scene_io_json.h"

#include "scene/atomic_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace wavelit::scene {

namespace fs = std::filesystem;
using util::ErrorKind;
using util::makeError;

namespace {

// " at line N" for the overflowing literal quoted in nlohmann's "number overflow parsing '1e999'"
// (its first occurrence in the text), so a hand-edited file says where to look.
std::string numberOverflowPlace(const std::string& text, const std::string& reason) {
    const size_t open = reason.find('\''), close = reason.rfind('\'');
    if (open == std::string::npos || close <= open + 1) return {};
    const size_t at = text.find(reason.substr(open + 1, close - open - 1));
    if (at == std::string::npos) return {};
    return " at line " + std::to_string(1 + std::count(text.begin(), text.begin() + ptrdiff_t(at), '\n'));
}

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

} // namespace

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

util::Status writeJson(const Json& doc, const std::string& path) {
    return writeFileAtomic(path, doc.dump(2) + "\n");
}

} // namespace wavelit::scene
