// A small relighting test scene built in code (tests only): a 2-triangle ground, a cube resting
// on it, a second cube far away, a glossy and a diffuse material, an equirect environment with a
// bright patch (so rotation matters) and one light of each local kind plus a sun.
#pragma once

#include "relight/relight_preview.h"
#include "scene/change_set.h"
#include "scene/scene.h"

#include <memory>

namespace wavelit::relight::testing {

inline std::shared_ptr<scene::TriangleMesh> groundMesh(float h) {
    auto m = std::make_shared<scene::TriangleMesh>();
    m->positions = {{-h, 0, -h}, {h, 0, -h}, {h, 0, h}, {-h, 0, h}};
    m->indices = {0, 2, 1, 0, 3, 2};
    return m;
}

inline std::shared_ptr<scene::TriangleMesh> cubeMesh(float h) {
    auto m = std::make_shared<scene::TriangleMesh>();
    for (int i = 0; i < 8; ++i)
        m->positions.push_back({(i & 1) ? h : -h, (i & 2) ? h : -h, (i & 4) ? h : -h});
    m->indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                  2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    return m;
}

inline scene::Scene makeRelightScene() {
    scene::Scene s;
    s.camera.position = {0.0f, 2.5f, 5.0f};
    s.camera.target = {0.0f, 0.3f, 0.0f};
    scene::Material diffuse;
    diffuse.id = 1;
    diffuse.name = "matte";
    diffuse.brdf = "lambert";
    diffuse.baseColor = {0.7f, 0.6f, 0.5f};
    scene::Material glossy;
    glossy.id = 2;
    glossy.name = "shiny";
    glossy.brdf = "ggx";
    glossy.baseColor = {0.9f, 0.8f, 0.6f};
    glossy.roughness = 0.3f;
    s.materials = {diffuse, glossy};
    scene::Object ground;
    ground.id = 3;
    ground.name = "ground";
    ground.mesh = groundMesh(3.0f);
    ground.materialId = 1;
    scene::Object box;
    box.id = 4;
    box.name = "box";
    box.mesh = cubeMesh(0.5f);
    box.transform.translation = {0.0f, 0.5f, 0.0f};
    box.materialId = 2;
    scene::Object far = box;
    far.id = 5;
    far.name = "far";
    far.transform.translation = {0.0f, -20.0f, -40.0f}; // far below the ground's horizon
    s.objects = {ground, box, far};
    auto env = std::make_shared<util::ImageRGB>(16, 8, glm::vec3(0.2f, 0.3f, 0.5f));
    for (int y = 1; y < 3; ++y)
        for (int x = 3; x < 5; ++x) env->at(x, y) = glm::vec3(20.0f, 18.0f, 15.0f);
    s.lighting.environment.image = env;
    s.lighting.environment.path = "sky.exr";
    scene::Light point;
    point.id = 6;
    point.name = "bulb";
    point.type = scene::LightType::Point;
    point.position = {1.5f, 2.0f, 1.0f};
    point.intensity = 50.0f;
    scene::Light rect;
    rect.id = 7;
    rect.name = "panel";
    rect.type = scene::LightType::Rect;
    rect.position = {-1.5f, 2.0f, 0.5f};
    rect.direction = {0.5f, -1.0f, 0.0f};
    rect.size = {1.0f, 0.8f};
    rect.intensity = 80.0f;
    scene::Light sphere;
    sphere.id = 8;
    sphere.name = "globe";
    sphere.type = scene::LightType::Sphere;
    sphere.position = {0.0f, 2.5f, -1.5f};
    sphere.radius = 0.4f;
    sphere.intensity = 60.0f;
    scene::Light sun;
    sun.id = 9;
    sun.name = "sun";
    sun.type = scene::LightType::Sun;
    sun.direction = {-0.3f, -1.0f, -0.4f};
    sun.intensity = 3.0f;
    sun.angularDiameterDeg = 5.0f;
    s.lighting.lights = {point, rect, sphere, sun};
    return s;
}

// Small enough for a fast test, with truncation on (16 of 256 coefficients).
inline RelightSettings smallSettings() {
    RelightSettings r;
    r.width = 20;
    r.height = 16;
    r.level = 4;
    r.keep = 16;
    r.threads = 2;
    return r;
}

} // namespace wavelit::relight::testing
