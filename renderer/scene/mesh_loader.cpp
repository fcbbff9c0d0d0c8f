#include "scene/mesh_loader.h"

#include "scene/load_guard.h"
#include "scene/mesh_loader_ply.h"
#include "util/path_util.h"

#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

namespace {

// A triangle is zero-area when |e1 x e2| is below float round-off of its edge lengths squared:
// positions carry ~6e-8 relative error, so anything smaller is indistinguishable from a sliver of
// collinear points.
constexpr float kDegenerateRelativeArea = 1e-7f;

bool isDegenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    return glm::length(glm::cross(e1, e2)) <= kDegenerateRelativeArea * (glm::dot(e1, e1) + glm::dot(e2, e2));
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Area-weighted vertex normals over the kept triangles; used when the file's (or Assimp's)
// normals are missing or broken.
std::vector<glm::vec3> smoothNormals(const TriangleMesh& m) {
    std::vector<glm::vec3> n(m.positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const uint32_t* i = &m.indices[3 * t];
        const glm::vec3 f = glm::cross(m.positions[i[1]] - m.positions[i[0]], m.positions[i[2]] - m.positions[i[0]]);
        for (int k = 0; k < 3; ++k) n[i[k]] += f;
    }
    for (auto& v : n) {
        const float len = glm::length(v);
        v = len > 0.0f ? v / len : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    return n;
}

// Assimp 5.2's glTF 2 reader allocates a GLB chunk's stated length before reading it: a 29-byte
// file stating a 4 GB JSON chunk made it allocate 4 GB (fuzz_gltf findings). A file Assimp would read
// as GLB (it starts with the magic "glTF") is refused here unless its header and every chunk it
// states fit in the file.
util::Status checkGlbChunks(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const uint64_t size = uint64_t(in.tellg());
    in.seekg(0);
    auto u32 = [&](uint32_t& v) {
        uint8_t b[4];
        if (!in.read(reinterpret_cast<char*>(b), 4)) return false;
        v = uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
        return true;
    };
    uint32_t magic = 0, version = 0, length = 0;
    if (!u32(magic) || magic != 0x46546c67u) return util::okStatus(); // "glTF"
    auto bad = [&](const std::string& what) {
        return makeError(ErrorKind::Format, path, "cannot read mesh: GLB " + what + " (the file has " + std::to_string(size) + " bytes)");
    };
    if (!u32(version) || !u32(length)) return bad("header is truncated");
    // The stated length bounds the chunks walked below, so it must hold at least the header and
    // the JSON chunk's header (a stated length of 1 skipped every check: fuzz_gltf finding).
    if (length > size || length < 20) return bad("header states " + std::to_string(length) + " bytes");
    for (uint64_t at = 12; at + 8 <= length; ) {
        uint32_t chunkLength = 0, chunkType = 0;
        in.seekg(std::streamoff(at));
        if (!u32(chunkLength) || !u32(chunkType)) return bad("chunk header at byte " + std::to_string(at) + " is truncated");
        if (at + 8 + chunkLength > length)
            return bad("chunk at byte " + std::to_string(at) + " states " + std::to_string(chunkLength) + " bytes");
        at += 8 + uint64_t(chunkLength);
    }
    return util::okStatus();
}

// Assimp 5.2's glTF 2 reader dereferences a null accessor for a primitive without a POSITION
// attribute drawn as lines (fuzz_gltf finding: SEGV). Such a primitive has no geometry to load, so a
// glTF (.gltf, or the JSON chunk of a .glb) any of whose primitives lacks POSITION is refused here.
// JSON the check cannot parse is left to Assimp, which reports it.
util::Status checkGltfPrimitives(const std::string& path, const std::string& ext) {
    if (ext != ".gltf" && ext != ".glb") return util::okStatus();
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (ext == ".glb" || text.rfind("glTF", 0) == 0) { // the first chunk, when it is JSON
        if (text.size() < 20 || text.compare(16, 4, "JSON") != 0) return util::okStatus();
        const uint32_t length = uint32_t(uint8_t(text[12])) | uint32_t(uint8_t(text[13])) << 8 |
                                uint32_t(uint8_t(text[14])) << 16 | uint32_t(uint8_t(text[15])) << 24;
        text = text.substr(20, length);
    }
    // Assimp's JSON parser passes bytes that are not UTF-8, nlohmann's refuses them: they can only
    // matter inside strings, so they become '?' for this check (the finding held such a byte).
    for (char& c : text)
        if (uint8_t(c) >= 0x80) c = '?';
    const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) return util::okStatus();
    const auto meshes = doc.find("meshes");
    if (meshes == doc.end() || !meshes->is_array()) return util::okStatus();
    for (size_t m = 0; m < meshes->size(); ++m) {
        const nlohmann::json& mesh = (*meshes)[m];
        const auto primitives = mesh.is_object() ? mesh.find("primitives") : mesh.end();
        if (!mesh.is_object() || primitives == mesh.end() || !primitives->is_array()) continue;
        for (size_t p = 0; p < primitives->size(); ++p) {
            const nlohmann::json& primitive = (*primitives)[p];
            const auto attributes = primitive.is_object() ? primitive.find("attributes") : primitive.end();
            if (!primitive.is_object() || attributes == primitive.end() || !attributes->is_object() ||
                !attributes->contains("POSITION"))
                return makeError(ErrorKind::Format, path, "cannot read mesh: glTF mesh " + std::to_string(m) + " primitive " +
                                                              std::to_string(p) + " has no POSITION attribute");
        }
    }
    return util::okStatus();
}

// Only the readers of the file's extension may read it. When those decline a file, Assimp asks all
// of its ~70 importers whether the bytes look like theirs, and some are not safe on arbitrary bytes:
// a .gltf holding the word "vertexarray" reached the OpenGEX parser, which read past its buffer
// (fuzz_gltf finding, AddressSanitizer). The others are unregistered from this importer (Assimp then
// no longer owns them: they are deleted here).
util::Status keepOnlyReadersOf(Assimp::Importer& importer, const std::string& ext, const std::string& path) {
    std::vector<Assimp::BaseImporter*> others;
    size_t readers = 0;
    for (size_t i = 0; i < importer.GetImporterCount(); ++i) {
        const aiImporterDesc* info = importer.GetImporterInfo(i);
        std::istringstream list(info && info->mFileExtensions ? info->mFileExtensions : "");
        bool reads = false;
        for (std::string e; list >> e;) reads = reads || "." + e == ext;
        if (reads)
            ++readers;
        else
            others.push_back(importer.GetImporter(i));
    }
    if (readers == 0)
        return makeError(ErrorKind::Unsupported, path, "cannot read mesh: no mesh reader for '" + ext + "' files");
    for (Assimp::BaseImporter* other : others)
        if (importer.UnregisterLoader(other) == aiReturn_SUCCESS) delete other;
    return util::okStatus();
}

// Assimp's post-processing trusts the faces a reader made, and Assimp 5.2's readers can make faces
// it cannot handle from malformed files (its own validation lets them through): a mesh stating
// polygons it does not have made triangulation assert (`validate` aborted, exit 134), and faces
// without vertices from a garbled PLY face list crashed a later step (SIGBUS, exit 135) — fuzz_ply
// findings. The raw meshes are checked before post-processing sees them.
util::Status checkRawMeshes(const aiScene* raw, const std::string& path) {
    for (unsigned mi = 0; mi < raw->mNumMeshes; ++mi) {
        const aiMesh* m = raw->mMeshes[mi];
        bool polygon = false;
        for (unsigned f = 0; f < m->mNumFaces; ++f) {
            const aiFace& face = m->mFaces[f];
            if (face.mNumIndices == 0 || !face.mIndices)
                return makeError(ErrorKind::Format, path, "cannot read mesh: mesh " + std::to_string(mi) + " face " +
                                                              std::to_string(f) + " has no vertices (malformed face list)");
            for (unsigned i = 0; i < face.mNumIndices; ++i)
                if (face.mIndices[i] >= m->mNumVertices)
                    return makeError(ErrorKind::Format, path, "cannot read mesh: mesh " + std::to_string(mi) + " face " +
                                                                  std::to_string(f) + " names vertex " + std::to_string(face.mIndices[i]) +
                                                                  " of " + std::to_string(m->mNumVertices));
            polygon = polygon || face.mNumIndices > 3;
        }
        if ((m->mPrimitiveTypes & aiPrimitiveType_POLYGON) && !polygon)
            return makeError(ErrorKind::Format, path, "cannot read mesh: mesh " + std::to_string(mi) +
                                                          " states polygons but has none (malformed face list)");
    }
    return util::okStatus();
}

} // namespace

bool isMeshExtension(const std::string& ext) {
    static const char* known[] = {".obj", ".gltf", ".glb", ".ply", ".fbx", ".stl", ".dae", ".3ds", ".off"};
    for (const char* k : known)
        if (ext == k) return true;
    return false;
}

namespace {

util::Result<TriangleMesh> loadMeshUnguarded(const std::string& path, std::vector<std::string>* warnings) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return makeError(ErrorKind::NotFound, path, "no such mesh file");
    if (auto s = checkPlyFile(path, util::lowerExtension(path)); !s) return s.error();
    if (auto s = checkGlbChunks(path); !s) return s.error();
    if (auto s = checkGltfPrimitives(path, util::lowerExtension(path)); !s) return s.error();
    Assimp::Importer importer;
    if (auto s = keepOnlyReadersOf(importer, util::lowerExtension(path), path); !s) return s.error();
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // Read without post-processing first: NaN positions must be rejected before the
    // normal generator and vertex joiner see them.
    const aiScene* raw = importer.ReadFile(path, aiProcess_ValidateDataStructure);
    if (!raw) return makeError(ErrorKind::Format, path, std::string("cannot read mesh: ") + importer.GetErrorString());
    for (unsigned mi = 0; mi < raw->mNumMeshes; ++mi) {
        const aiMesh* m = raw->mMeshes[mi];
        for (unsigned v = 0; v < m->mNumVertices; ++v)
            if (!finite(glm::vec3(m->mVertices[v].x, m->mVertices[v].y, m->mVertices[v].z)))
                return makeError(ErrorKind::Invalid, path, "vertex " + std::to_string(v) + " is NaN or infinite");
    }
    if (auto c = checkRawMeshes(raw, path); !c) return c.error();
    const aiScene* s = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                                    aiProcess_GenSmoothNormals | aiProcess_PreTransformVertices |
                                                    aiProcess_SortByPType);
    if (!s) return makeError(ErrorKind::Format, path, std::string("cannot process mesh: ") + importer.GetErrorString());

    TriangleMesh mesh;
    bool haveNormals = true, haveUvs = true;
    size_t faces = 0, degenerate = 0;
    for (unsigned mi = 0; mi < s->mNumMeshes; ++mi) {
        const aiMesh* m = s->mMeshes[mi];
        if (!(m->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        const uint32_t base = uint32_t(mesh.positions.size());
        haveNormals = haveNormals && m->HasNormals();
        haveUvs = haveUvs && m->HasTextureCoords(0);
        for (unsigned v = 0; v < m->mNumVertices; ++v) {
            mesh.positions.emplace_back(m->mVertices[v].x, m->mVertices[v].y, m->mVertices[v].z);
            if (m->HasNormals()) mesh.normals.emplace_back(m->mNormals[v].x, m->mNormals[v].y, m->mNormals[v].z);
            if (m->HasTextureCoords(0)) mesh.uvs.emplace_back(m->mTextureCoords[0][v].x, m->mTextureCoords[0][v].y);
        }
        for (unsigned f = 0; f < m->mNumFaces; ++f) {
            const aiFace& face = m->mFaces[f];
            if (face.mNumIndices != 3) continue;
            ++faces;
            const uint32_t a = base + face.mIndices[0], b = base + face.mIndices[1], c = base + face.mIndices[2];
            if (isDegenerate(mesh.positions[a], mesh.positions[b], mesh.positions[c])) {
                ++degenerate;
                continue;
            }
            mesh.indices.insert(mesh.indices.end(), {a, b, c});
        }
    }
    if (faces == 0) return makeError(ErrorKind::Invalid, path, "mesh has no faces");
    if (mesh.indices.empty())
        return makeError(ErrorKind::Invalid, path, "all " + std::to_string(faces) + " triangles have zero area");
    if (degenerate && warnings)
        warnings->push_back(path + ": skipped " + std::to_string(degenerate) + " zero-area triangles of " +
                            std::to_string(faces));
    if (!haveUvs) mesh.uvs.clear();
    bool normalsOk = haveNormals && mesh.normals.size() == mesh.positions.size();
    for (size_t i = 0; normalsOk && i < mesh.normals.size(); ++i)
        normalsOk = finite(mesh.normals[i]) && glm::length(mesh.normals[i]) > 0.5f;
    if (!normalsOk) mesh.normals = smoothNormals(mesh);
    return mesh;
}

} // namespace

util::Result<TriangleMesh> loadMesh(const std::string& path, std::vector<std::string>* warnings) {
    return guardLoad<TriangleMesh>(path, [&] { return loadMeshUnguarded(path, warnings); });
}

} // namespace wavelit::scene
