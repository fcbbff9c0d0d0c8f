#include "scene/property_registry.h"

#include "plugins/brdf.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace wavelit::scene {
namespace {

// A default-constructed entity of each kind, to check declared defaults against the structs.
struct Defaults {
    Camera camera;
    Material material;
    Object object;
    Environment environment;
    Light light;
    RenderDefaults render;
    const void* of(EntityKind k) const {
        switch (k) {
        case EntityKind::Camera: return &camera;
        case EntityKind::Material: return &material;
        case EntityKind::Object: return &object;
        case EntityKind::Environment: return &environment;
        case EntityKind::Light: return &light;
        case EntityKind::Render: return &render;
        }
        return nullptr;
    }
};

Light lightOf(LightType type) {
    Light l;
    l.type = type;
    return l;
}

TEST(PropertyRegistry, EveryPropertyIsFullyDeclared) {
    const Defaults d;
    for (EntityKind kind : kAllEntityKinds) {
        std::set<std::string> names;
        for (const PropertyInfo& p : properties(kind)) {
            SCOPED_TRACE(std::string(entityKindName(kind)) + "." + p.name);
            EXPECT_TRUE(names.insert(p.name).second) << "duplicate name";
            EXPECT_EQ(p.entity, kind);
            EXPECT_FALSE(p.label.empty());
            EXPECT_FALSE(p.tooltip.empty());
            EXPECT_LE(p.min, p.max);
            EXPECT_EQ(p.get(d.of(kind)), p.defaultValue);
            if (!p.required) {
                EXPECT_TRUE(checkValue(p, p.defaultValue).ok());
            }
            if (p.type == PropertyType::Enum) {
                EXPECT_FALSE(p.enumOptions.empty());
            }
            EXPECT_EQ(findProperty(kind, p.name), &p);
        }
    }
    EXPECT_EQ(findProperty(EntityKind::Material, "roughnes"), nullptr);
}

TEST(PropertyRegistry, ChecksTypesRangesOptionsAndPaths) {
    const PropertyInfo& roughness = *findProperty(EntityKind::Material, "roughness");
    EXPECT_TRUE(checkValue(roughness, 0.0f).ok());
    EXPECT_TRUE(checkValue(roughness, 1.0f).ok());
    EXPECT_FALSE(checkValue(roughness, 1.01f).ok());
    EXPECT_FALSE(checkValue(roughness, std::nanf("")).ok());
    EXPECT_FALSE(checkValue(roughness, 1).ok()); // an int is not a float: no silent conversion
    const auto err = checkValue(roughness, 2.0f);
    EXPECT_EQ(err.error().reason, "roughness: 2 is outside [0, 1]");
    const PropertyInfo& type = *findProperty(EntityKind::Light, "type");
    EXPECT_TRUE(checkValue(type, std::string("sun")).ok());
    EXPECT_EQ(checkValue(type, std::string("laser")).error().reason,
              "type: 'laser' is not one of point, sphere, rect, spot, sun");
    const PropertyInfo& mesh = *findProperty(EntityKind::Object, "mesh");
    EXPECT_TRUE(checkValue(mesh, std::string("../meshes/torus.obj")).ok());
    for (const char* bad : {"/etc/passwd", "~/x.obj", "C:/x.obj", "\\\\server\\x.obj"})
        EXPECT_FALSE(checkValue(mesh, std::string(bad)).ok()) << bad;
}

TEST(PropertyRegistry, GenericGetSetByName) {
    Scene s;
    s.lighting.lights.push_back(lightOf(LightType::Sun));
    s.lighting.lights[0].id = 7;
    ASSERT_TRUE(setProperty(s, {EntityKind::Light, 7}, "angularDiameter", 1.5f).ok());
    EXPECT_FLOAT_EQ(s.lighting.lights[0].angularDiameterDeg, 1.5f);
    ASSERT_TRUE(setProperty(s, {EntityKind::Light, 7}, "type", std::string("rect")).ok());
    EXPECT_EQ(s.lighting.lights[0].type, LightType::Rect);
    EXPECT_EQ(*getProperty(s, {EntityKind::Light, 7}, "type"), PropertyValue(std::string("rect")));
    ASSERT_TRUE(setProperty(s, {EntityKind::Camera}, "fov", 55.0f).ok());
    EXPECT_FLOAT_EQ(s.camera.verticalFovDeg, 55.0f);
    EXPECT_EQ(getProperty(s, {EntityKind::Light, 8}, "type").error().reason, "light 8 not found");
    EXPECT_EQ(setProperty(s, {EntityKind::Camera}, "zoom", 1.0f).error().reason, "camera has no property 'zoom'");
}

// A material's BRDF is one of the plugin registry's names: the panel offers them in a combo box,
// and setProperty (scripts, undo) refuses any other with a message listing them.
TEST(PropertyRegistry, BrdfIsAChoiceOfThePluginRegistry) {
    const PropertyInfo& brdf = *findProperty(EntityKind::Material, "brdf");
    EXPECT_EQ(brdf.type, PropertyType::Enum);
    EXPECT_EQ(brdf.enumOptions, plugins::brdfNames());
    Scene s;
    s.materials.push_back(Material{.id = 3, .name = "gold"});
    ASSERT_TRUE(setProperty(s, {EntityKind::Material, 3}, "brdf", std::string("ggx")).ok());
    EXPECT_EQ(s.materials[0].brdf, "ggx");
    const auto refused = setProperty(s, {EntityKind::Material, 3}, "brdf", std::string("no_such_brdf"));
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().reason, "brdf: unknown BRDF 'no_such_brdf'; known: lambert, ggx, glossy, phong, blinn, ward, measured");
    EXPECT_EQ(s.materials[0].brdf, "ggx");
    for (const std::string& name : plugins::brdfNames()) EXPECT_TRUE(checkValue(brdf, name).ok()) << name;
}

TEST(PropertyRegistry, LightPropertiesApplyByType) {
    const Light sun = lightOf(LightType::Sun), sphere = lightOf(LightType::Sphere);
    EXPECT_FALSE(propertyApplies(*findProperty(EntityKind::Light, "position"), &sun));
    EXPECT_TRUE(propertyApplies(*findProperty(EntityKind::Light, "angularDiameter"), &sun));
    EXPECT_TRUE(propertyApplies(*findProperty(EntityKind::Light, "radius"), &sphere));
    EXPECT_FALSE(propertyApplies(*findProperty(EntityKind::Light, "direction"), &sphere));
}

// docs/file-formats.md documents the properties; it must not fall behind the registry.
TEST(PropertyRegistry, EveryPropertyIsDocumented) {
    const std::filesystem::path doc = std::filesystem::path(WAVELIT_RESOURCE_DIR) / "../docs/file-formats.md";
    std::ifstream in(doc);
    ASSERT_TRUE(in) << doc;
    std::stringstream text;
    text << in.rdbuf();
    for (EntityKind kind : kAllEntityKinds)
        for (const PropertyInfo& p : properties(kind)) {
            const std::string row = std::string("| ") + entityKindName(kind) + " | `" + p.name + "` |";
            EXPECT_NE(text.str().find(row), std::string::npos) << row;
        }
}

} // namespace
} // namespace wavelit::scene
