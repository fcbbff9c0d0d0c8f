// The scene model everything edits and renders (architecture.md §3, §6). Plain data: the property
// registry (property_registry.h) describes every editable field once, and JSON IO, validation,
// the editor's panels and scripting are all driven from that description.
//
// Conventions: world space right-handed, +Y up, metres; radiance linear Rec.709.
// Ids are stable for the lifetime of an entity (saved in files) and unique per kind (materials,
// objects and lights each; EntityRef and Invalidation carry the kind); names are unique per kind.
// New entities take nextId(), which is unique across all kinds.
//
// `extras` (on the document roots and on every entity): the JSON text of the object a file stores
// under "extras" — data of other tools that Wavelit keeps and never reads. Loading stores it as
// compact JSON, saving writes it back unchanged; empty when the file has none (docs/file-formats.md).
#pragma once

#include "plugins/brdf.h"
#include "util/image.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace wavelit::scene {

using EntityId = uint64_t;
inline constexpr EntityId kInvalidId = 0;

// Perspective camera: vertical field of view in degrees, position + target + up (architecture.md §3).
struct Camera {
    glm::vec3 position{0.0f, 1.0f, 4.0f};
    glm::vec3 target{0.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float verticalFovDeg = 40.0f;
    float exposureEv = 0.0f; // display only: never resets accumulation
    std::string extras{};
};

// A triangle mesh in object space, as loaded through Assimp. Normals are per vertex (may be
// empty: then geometric normals are used). Immutable once loaded; shared between scene copies.
struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices; // 3 per triangle
    size_t triangleCount() const { return indices.size() / 3; }
};

// A material: a BRDF plugin by name (plugins/) and its parameters. The name must be one of
// plugins::brdfNames() (the registry's "brdf" property checks it; loading refuses any other);
// each plugin says which parameters it reads (plugins::Brdf::parameters). A new material gets
// the registry's default plugin (plugins::defaultBrdfName()).
struct Material {
    EntityId id = kInvalidId;
    std::string name;
    std::string brdf = plugins::defaultBrdfName();
    glm::vec3 baseColor{0.8f, 0.8f, 0.8f};
    float roughness = 0.5f; // in [0, 1]; GGX alpha = roughness^2 (architecture.md §3)
    float anisotropy = 0.0f; // in [0, 1]; `ward` stretches its lobe along the tangent
    glm::vec3 emission{0.0f}; // emitted radiance, W/(m^2 sr)
    // A BRDF data file (plugins::brdfReadsFile: a MERL-layout table), relative to the scene file
    // like a mesh path; loaded with the meshes (scene_io's loadAssets), shared between copies.
    std::string brdfFile{};
    std::shared_ptr<const plugins::BrdfTable> brdfTable{};
    std::string extras{};
};

// The parameters a material's BRDF plugin reads.
plugins::BrdfParams brdfParamsOf(const Material& m);

// Object transform: translation, then Euler XYZ rotation in degrees, then scale (T * R * S).
struct Transform {
    glm::vec3 translation{0.0f};
    glm::vec3 rotationDeg{0.0f};
    glm::vec3 scale{1.0f};
    glm::mat4 matrix() const;
};

struct Object {
    EntityId id = kInvalidId;
    std::string name;
    std::string meshPath; // as written in the file: relative to the scene file
    std::shared_ptr<const TriangleMesh> mesh;
    Transform transform;
    EntityId materialId = kInvalidId;
    std::string extras{};
};

// HDR environment: equirectangular map (architecture.md §3 mapping), yaw rotation about +Y in degrees.
// Radiance = map(d) * intensity * tint. An empty path means a constant environment of
// `intensity * tint` (used by furnace tests and as a neutral default).
struct Environment {
    std::string path; // relative to the file that references it
    std::shared_ptr<const util::ImageRGB> image;
    float rotationDeg = 0.0f;
    float intensity = 1.0f;
    glm::vec3 tint{1.0f};
    // LightMix "Extract sun" (docs/lightmix.md, scene/environment_mask.h): a cap of the map, in the
    // map's own frame, whose texels count as black (their energy became a sun light). `image` is
    // the map with the mask applied; the file is untouched. maskRadiusDeg 0 = no mask.
    glm::vec3 maskDirection{0.0f, 1.0f, 0.0f};
    float maskRadiusDeg = 0.0f;
    std::string extras{};
};

enum class LightType { Point, Sphere, Rect, Spot, Sun };

// Analytic lights in physical units. `intensity` is:
//   Point/Sphere/Spot: radiant power in W (Spot: power of the equivalent unshadowed point light);
//   Rect: radiant power in W leaving the front face;  Sun: irradiance in W/m^2 on a plane facing it.
// Colour multiplies intensity (linear Rec.709, usually normalised to luminance 1).
struct Light {
    EntityId id = kInvalidId;
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 color{1.0f};
    float intensity = 100.0f;
    glm::vec3 position{0.0f, 3.0f, 0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // Spot/Sun/Rect: the way light travels
    float radius = 0.0f;                     // Sphere radius, m
    glm::vec2 size{1.0f, 1.0f};              // Rect width x height, m
    float coneInnerDeg = 20.0f;              // Spot full-intensity half angle
    float coneOuterDeg = 30.0f;              // Spot cut-off half angle
    float angularDiameterDeg = 0.53f;        // Sun
    // LightMix layer (docs/lightmix.md): lights with the same group share one radiance layer;
    // empty = the light's own layer, named after the light.
    std::string group{};
    // Muted: emits nothing (LightMix mute, docs/lightmix.md); kept in the file so the setup can be
    // unmuted later with its intensity and colour intact.
    bool muted = false;
    std::string extras{};
};

// A lighting setup (*.wllight): loadable onto any scene.
struct LightingSetup {
    std::string name;
    Environment environment;
    std::vector<Light> lights;
    std::string extras{}; // the *.wllight root's (or an inline "lighting" object's) extras
};

struct RenderDefaults {
    int width = 512;
    int height = 512;
    int bounces = 4;
    std::string extras{};
};

struct Scene {
    std::string name;
    Camera camera;
    std::vector<Material> materials;
    std::vector<Object> objects;
    LightingSetup lighting;
    std::string lightingPath; // non-empty when the lighting setup lives in its own *.wllight
    RenderDefaults render;
    std::string extras{}; // the *.wlscene root's extras

    const Material* findMaterial(EntityId id) const;
    const Object* findObject(EntityId id) const;
    const Light* findLight(EntityId id) const;
    EntityId nextId() const; // one past the largest id in use
};

} // namespace wavelit::scene
