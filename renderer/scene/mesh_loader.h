// Meshes through Assimp (OBJ, glTF/GLB, PLY, FBX, ...), flattened into one object-space
// TriangleMesh: node transforms applied, polygons triangulated, identical vertices joined, smooth
// normals generated where the file has none, points and lines dropped.
// The file's extension chooses Assimp's reader: bytes are never handed to a reader of another
// format (Assimp would otherwise let every importer it has guess). Rejected (error naming the file):
// extensions no reader has, unreadable files, NaN/Inf positions, no faces, only zero-area faces. Zero-area triangles among good ones are skipped with a warning (they carry no area to
// shade or sample, and their normals are undefined).
#pragma once

#include "scene/scene.h"
#include "util/result.h"

#include <string>
#include <vector>

namespace wavelit::scene {

util::Result<TriangleMesh> loadMesh(const std::string& path, std::vector<std::string>* warnings = nullptr);

// True for the extensions loadMesh is meant for (a hint for `validate`; loadMesh reads any
// extension an Assimp reader declares).
bool isMeshExtension(const std::string& lowerExt);

} // namespace wavelit::scene
