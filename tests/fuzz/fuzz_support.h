// Shared by the libFuzzer harnesses (tests/fuzz/README.md). The loaders read files — a scene's
// meshes, lighting setup and environment map are paths relative to it — so each input is written
// to a file with the reader's extension inside a private temporary tree, and the public loader
// reads it exactly as `wavelit-cli validate` would. The tree mirrors the repository's layout with
// tiny stand-ins for the bundled assets, so the checked-in scenes load completely:
//   <tmp>/resources/meshes/quad.obj       what tests/data/bad/*.wlscene reference (../../../resources/...)
//   <tmp>/tests/data/{meshes,envmaps,lighting}/  what resources/scenes/*.wlscene reference (../meshes/...)
//   <tmp>/tests/data/bad/                 the input, beside copies of the small bad-corpus files
// A finding is reported by abort() after printing what broke: an error that does not name the file,
// an error from the loaders' last-resort exception catch (scene/load_guard.h), or a loaded result
// that breaks its header's contract.
#pragma once

#include "util/result.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace wavelit::fuzz {

// The folder inputs are written to (<tmp>/tests/data/bad), created with the stand-ins on first use.
const std::string& inputFolder();

// Writes the bytes to inputFolder()/name and returns the path.
std::string writeInput(const uint8_t* data, size_t size, const std::string& name);

// Prints "fuzz finding: <what>" (and the error) to stderr and aborts.
[[noreturn]] void finding(const std::string& what);

// The contract of every loader error: the message names `path`, and the loaders' last-resort catch
// did not make it (scene::unexpectedLoadFailures() did not move: no exception escaped the checks).
void checkError(const util::Error& error, const std::string& path);

} // namespace wavelit::fuzz
