// The structural checks readExr and readExrAttributes run before OpenEXR 3.1 opens a file. OpenEXR
// allocates from what a file states before reading what it describes: an attribute's stated size,
// and, when it opens the file, line buffers sized from the data window (bytes per line x lines
// per chunk); a few hundred corrupt bytes could cost gigabytes (fuzz_exr findings,
// tests/fuzz/FINDINGS.md). The checks hold each attribute against the bytes after it, each data
// window against the pixel limit, and the offset tables and chunk headers against the file's
// size, and refuse, naming the file and the problem, what does not fit. A file they cannot follow
// (not an EXR, a header OpenEXR would refuse) is left to OpenEXR, which reports it.
#pragma once

#include "util/result.h"

#include <string>

namespace wavelit::scene {

// Every header of the file (all parts of a multi-part file): each attribute's stated size against
// the bytes after it, and each data window against `maxDimension` pixels per side (OpenEXR sizes
// its line buffers from the window when it opens a file).
util::Status checkExrHeaders(const std::string& path, int maxDimension);

// checkExrHeaders, then each part's offset table (its chunk count follows from the data window,
// compression and tiling) and every chunk's header: each chunk must lie inside the file and its
// stated data size fit in the bytes after it.
util::Status checkExrLayout(const std::string& path, int maxDimension);

} // namespace wavelit::scene
