// The PLY check loadMesh runs before Assimp sees a file: Assimp 5.2's PLY reader (what Debian 12
// ships) trusts what a file states, and malformed headers and element data made it hang or
// allocate gigabytes (fuzz_ply findings, tests/fuzz/FINDINGS.md). The check reads the header and
// walks the element data the way that reader does, and refuses, naming the file and the problem,
// what it could not read safely.
#pragma once

#include "util/result.h"

#include <string>

namespace wavelit::scene {

// `lowerExt` is the file's extension in lower case. Files that Assimp would not read as PLY (not a
// .ply and not starting with "ply") pass unchecked.
util::Status checkPlyFile(const std::string& path, const std::string& lowerExt);

} // namespace wavelit::scene
