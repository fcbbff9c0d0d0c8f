// The last line of defence of every loader (architecture.md §9: bad input is a Result, never an
// exception): loadScene, loadLightingSetup, loadImage and loadMesh run their body inside guardLoad,
// which turns an exception that a parser library threw past the checks into an error naming the
// file. Such an error is a bug — the input should have been refused with its own reason — so its
// reason starts with kUnexpectedLoadFailure and unexpectedLoadFailures() counts it: the fuzz
// harnesses (tests/fuzz) report a count that moved as a finding, while users get a message and keep
// working. (A count, not the message: a file can contain any text, and errors quote files.)
#pragma once

#include "util/result.h"

#include <atomic>
#include <exception>
#include <new>
#include <string>
#include <string_view>

namespace wavelit::scene {

inline constexpr std::string_view kUnexpectedLoadFailure = "unexpected failure while reading: ";

// Exceptions guardLoad has caught in this process so far (any thread).
inline std::atomic<unsigned long long>& unexpectedLoadFailures() {
    static std::atomic<unsigned long long> count{0};
    return count;
}

template <typename T, typename Load>
util::Result<T> guardLoad(const std::string& file, Load&& load) noexcept {
    auto caught = [&](util::ErrorKind kind, const std::string& what) {
        ++unexpectedLoadFailures();
        return util::makeError(kind, file, std::string(kUnexpectedLoadFailure) + what);
    };
    try {
        return load();
    } catch (const std::bad_alloc&) {
        return caught(util::ErrorKind::Io, "out of memory");
    } catch (const std::exception& e) {
        return caught(util::ErrorKind::Format, e.what());
    } catch (...) {
        return caught(util::ErrorKind::Format, "unknown exception");
    }
}

} // namespace wavelit::scene
