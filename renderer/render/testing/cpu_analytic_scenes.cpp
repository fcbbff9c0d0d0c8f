#include "render/testing/cpu_analytic_scenes.h"

#include <cmath>

namespace wavelit::render {

scene::TriangleMesh makeUvSphere(int segments, int rings) {
    constexpr float kPi = 3.14159265358979323846f;
    scene::TriangleMesh mesh;
    for (int r = 0; r <= rings; ++r) {
        float theta = kPi * float(r) / float(rings);
        for (int s = 0; s <= segments; ++s) {
            float phi = 2.0f * kPi * float(s) / float(segments);
            glm::vec3 p(std::sin(theta) * std::cos(phi), std::cos(theta),
                        -std::sin(theta) * std::sin(phi));
            mesh.positions.push_back(p);
            mesh.normals.push_back(p);
            mesh.uvs.emplace_back(float(s) / float(segments), float(r) / float(rings));
        }
    }
    const uint32_t row = uint32_t(segments) + 1;
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            uint32_t a = uint32_t(r) * row + uint32_t(s), b = a + 1, c = a + row, d = c + 1;
            // Pole rows would give zero-area triangles: skip them.
            if (r != 0) mesh.indices.insert(mesh.indices.end(), {a, c, b});
            if (r != rings - 1) mesh.indices.insert(mesh.indices.end(), {b, c, d});
        }
    }
    return mesh;
}

scene::TriangleMesh makeGroundQuad(float halfSize) {
    const float h = halfSize;
    scene::TriangleMesh mesh;
    mesh.positions = {{-h, 0, -h}, {h, 0, -h}, {h, 0, h}, {-h, 0, h}};
    mesh.indices = {0, 2, 1, 0, 3, 2};
    return mesh;
}

std::shared_ptr<scene::Scene> makeFurnaceScene(const scene::Material& material,
                                               const glm::vec3& environment, int segments,
                                               int rings) {
    auto s = std::make_shared<scene::Scene>();
    s->name = "furnace";
    s->camera.position = glm::vec3(0.0f, 0.0f, 4.0f);
    s->camera.target = glm::vec3(0.0f);
    s->camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    s->camera.verticalFovDeg = 40.0f;
    scene::Material m = material;
    m.id = 1;
    s->materials.push_back(m);
    scene::Object o;
    o.id = 2;
    o.name = "sphere";
    o.mesh = std::make_shared<scene::TriangleMesh>(makeUvSphere(segments, rings));
    o.materialId = 1;
    s->objects.push_back(o);
    s->lighting.environment.intensity = 1.0f;
    s->lighting.environment.tint = environment;
    return s;
}

std::shared_ptr<scene::Scene> makeClosedSphereScene(const scene::Material& material) {
    auto s = makeFurnaceScene(material, glm::vec3(0.0f), 48, 24);
    s->name = "closed sphere";
    s->camera.position = glm::vec3(0.0f);
    s->camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    s->camera.verticalFovDeg = 90.0f;
    return s;
}

std::shared_ptr<scene::Scene> makePlaneScene(const scene::Material& material) {
    auto s = std::make_shared<scene::Scene>();
    s->camera.position = glm::vec3(0.0f, 3.0f, 3.0f);
    s->camera.target = glm::vec3(0.0f);
    s->camera.verticalFovDeg = 40.0f;
    scene::Material m = material;
    m.id = 1;
    s->materials.push_back(m);
    scene::Object o;
    o.id = 2;
    o.materialId = 1;
    o.mesh = std::make_shared<scene::TriangleMesh>(makeGroundQuad(20.0f));
    s->objects.push_back(o);
    s->lighting.environment.intensity = 0.0f; // black: only the analytic lights
    return s;
}

} // namespace wavelit::render
