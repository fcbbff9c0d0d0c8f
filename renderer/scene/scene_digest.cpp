#include "scene/scene_digest.h"

#include "scene/property_registry.h"

#include <cstdio>
#include <type_traits>
#include <variant>

namespace wavelit::scene {

namespace {

class Fnv1a {
public:
    void bytes(const void* data, size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) m_hash = (m_hash ^ p[i]) * 0x100000001b3ULL;
    }
    template <typename T> void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof v);
    }
    void text(const std::string& s) {
        value(s.size()); // a length prefix, so ("ab", "c") and ("a", "bc") differ
        bytes(s.data(), s.size());
    }
    template <typename T> void array(const std::vector<T>& v) {
        value(v.size());
        bytes(v.data(), v.size() * sizeof(T));
    }
    uint64_t hash() const { return m_hash; }

private:
    uint64_t m_hash = 0xcbf29ce484222325ULL;
};

// Paths are left out: the assets they load are hashed instead (hashMesh, and the environment
// texels in sceneDigest).
void hashEntity(Fnv1a& h, EntityKind kind, const void* entity) {
    for (const PropertyInfo& info : properties(kind)) {
        if (info.change == ChangeKind::Display || info.type == PropertyType::Path) continue;
        h.text(info.name);
        const PropertyValue v = info.get(entity);
        h.value(v.index());
        std::visit([&](const auto& x) {
            if constexpr (std::is_same_v<std::decay_t<decltype(x)>, std::string>)
                h.text(x);
            else
                h.value(x);
        }, v);
    }
}

template <typename E> void hashList(Fnv1a& h, EntityKind kind, const std::vector<E>& list) {
    h.value(list.size());
    for (const E& e : list) {
        h.value(e.id); // objects name their material by id
        hashEntity(h, kind, &e);
    }
}

void hashMesh(Fnv1a& h, const TriangleMesh* mesh) {
    h.value(mesh != nullptr);
    if (!mesh) return;
    h.array(mesh->positions);
    h.array(mesh->normals);
    h.array(mesh->uvs);
    h.array(mesh->indices);
}

} // namespace

std::string sceneDigest(const Scene& scene) {
    Fnv1a h;
    hashEntity(h, EntityKind::Camera, &scene.camera);
    hashList(h, EntityKind::Material, scene.materials);
    hashList(h, EntityKind::Object, scene.objects);
    for (const Object& o : scene.objects) hashMesh(h, o.mesh.get());
    hashEntity(h, EntityKind::Environment, &scene.lighting.environment);
    const util::ImageRGB* env = scene.lighting.environment.image.get();
    h.value(env != nullptr);
    if (env) {
        h.value(env->width);
        h.value(env->height);
        h.array(env->pixels);
    }
    hashList(h, EntityKind::Light, scene.lighting.lights);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h.hash()));
    return hex;
}

} // namespace wavelit::scene
