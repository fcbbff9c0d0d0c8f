#include "scene/mesh_loader.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>

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

} // namespace

bool isMeshExtension(const std::string& ext) {
    static const char* known[] = {".obj", ".gltf", ".glb", ".ply", ".fbx", ".stl", ".dae", ".3ds", ".off"};
    for (const char* k : known)
        if (ext == k) return true;
    return false;
}

util::Result<TriangleMesh> loadMesh(const std::string& path, std::vector<std::string>* warnings) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return makeError(ErrorKind::NotFound, path, "no such mesh file");
    Assimp::Importer importer;
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

} // namespace wavelit::scene
