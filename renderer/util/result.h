// Result<T>: the error channel of every IO boundary (JSON, Assimp, OpenEXR, glslang, CLI args).
// Bad input is not a programming error: parsers convert their exceptions into an Error at their
// boundary, and errors never cross a thread, the frame loop or a Qt slot as exceptions.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace wavelit::util {

enum class ErrorKind {
    NotFound,      // file or referenced entity missing
    Io,            // read/write failure (permissions, full disk)
    Format,        // unparsable or corrupt content
    Invalid,       // parsed, but violates a constraint (non-square, NaN, negative...)
    Unsupported,   // newer version, unknown plugin, missing device feature
    Device,        // Vulkan failure or device loss
    Usage,         // bad command-line usage (CLI exit code 2)
};

const char* errorKindName(ErrorKind kind);

// An error names what failed (file), where inside it (JSON path, line, texel) and why, e.g.
// "city.exr: 2048x1024 is not square".
struct Error {
    ErrorKind kind = ErrorKind::Invalid;
    std::string file;   // may be empty when no file is involved
    std::string where;  // optional place inside the file: "/objects/2/material", "line 14"
    std::string reason;

    std::string message() const;
};

inline Error makeError(ErrorKind kind, std::string file, std::string reason, std::string where = {}) {
    return Error{kind, std::move(file), std::move(where), std::move(reason)};
}

template <typename T> class [[nodiscard]] Result {
public:
    Result(T value) : m_state(std::in_place_index<0>, std::move(value)) {}
    Result(Error error) : m_state(std::in_place_index<1>, std::move(error)) {}

    bool ok() const { return m_state.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { return std::get<0>(m_state); }
    const T& value() const& { return std::get<0>(m_state); }
    T&& value() && { return std::get<0>(std::move(m_state)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const { return std::get<1>(m_state); }

private:
    std::variant<T, Error> m_state;
};

// Result<void>: success or an Error.
struct Ok {};
using Status = Result<Ok>;
inline Status okStatus() { return Ok{}; }

} // namespace wavelit::util
