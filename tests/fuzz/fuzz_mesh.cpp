// Meshes through Assimp via scene::loadMesh: bytes -> input<WAVELIT_FUZZ_EXT> -> loadMesh. The
// glTF harness (WAVELIT_FUZZ_GLTF) writes input.glb when the bytes start with the binary magic
// "glTF" and input.gltf otherwise. An error must name the file; a loaded mesh must be what
// mesh_loader.h promises: triangles indexing existing vertices, finite positions, one usable normal
// (finite, length > 0.5) per vertex, UVs absent or one per vertex.
#include "fuzz_support.h"

#include "scene/mesh_loader.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace wavelit;
#ifdef WAVELIT_FUZZ_GLTF
    const char* ext = size >= 4 && std::memcmp(data, "glTF", 4) == 0 ? ".glb" : ".gltf";
#else
    const char* ext = WAVELIT_FUZZ_EXT;
#endif
    const std::string path = fuzz::writeInput(data, size, std::string("input") + ext);
    std::vector<std::string> warnings;
    auto mesh = scene::loadMesh(path, &warnings);
    if (!mesh) {
        fuzz::checkError(mesh.error(), path);
        return 0;
    }
    const scene::TriangleMesh& m = *mesh;
    if (m.indices.empty() || m.indices.size() % 3 != 0) fuzz::finding(std::to_string(m.indices.size()) + " indices");
    for (uint32_t i : m.indices)
        if (i >= m.positions.size()) fuzz::finding("index " + std::to_string(i) + " of " + std::to_string(m.positions.size()) + " vertices");
    if (m.normals.size() != m.positions.size()) fuzz::finding("normals do not match the vertices");
    if (!m.uvs.empty() && m.uvs.size() != m.positions.size()) fuzz::finding("uvs do not match the vertices");
    for (size_t v = 0; v < m.positions.size(); ++v) {
        if (!finite(m.positions[v])) fuzz::finding("vertex " + std::to_string(v) + " is not finite");
        if (!finite(m.normals[v]) || glm::length(m.normals[v]) <= 0.5f) // the loader's own test of a usable normal
            fuzz::finding("normal " + std::to_string(v) + " is unusable");
    }
    return 0;
}
