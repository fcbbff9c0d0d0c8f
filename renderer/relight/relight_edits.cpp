// RelightPreview::applyChanges: which factor an edit changed and where it can matter
// (relight_preview.h lists the cases; architecture.md §5.A).
#include "relight/relight_preview.h"

#include "relight/edit_rules.h"
#include "util/parallel_for.h"
#include "util/timer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace wavelit::relight {
namespace {

bool structural(const scene::Scene& a, const scene::Scene& b, const scene::ChangeSet& changes) {
    if (a.objects.size() != b.objects.size() || a.materials.size() != b.materials.size() ||
        a.lighting.lights.size() != b.lighting.lights.size())
        return true;
    for (const scene::Edit& e : changes.edits())
        if (std::holds_alternative<scene::EntityEdit>(e)) return true;
    return false;
}

bool anyOverlap(const TexelBits& a, const TexelBits& b) {
    for (size_t w = 0; w < a.size(); ++w)
        if (a[w] | b[w]) return true;
    return false;
}

// Whether a shadow ray from `origin` toward light k can pass through `sphere`: their bounding
// cones (the light's: its position and extent, the sun's: its angular radius; each widened by a
// texel radius, as a light texel's ray runs anywhere in its texel) meet. A moved object whose old
// and new spheres both miss the light's cone cannot change the light's shadow rays.
bool lightConeMeets(const scene::Light& light, const glm::vec3& origin, const BoundingSphere& sphere,
                    double texelRadius) {
    if (sphere.radius < 0.0f) return false;
    const glm::vec3 toSphere = sphere.centre - origin;
    const float sphereDistance = glm::length(toSphere);
    if (sphereDistance <= sphere.radius) return true;
    glm::vec3 axis;
    double half = 0.0;
    if (light.type == scene::LightType::Sun) {
        const float len = glm::length(light.direction);
        if (!(len > 0.0f)) return true;
        axis = -light.direction / len;
        half = 0.5 * double(light.angularDiameterDeg) * 3.14159265358979 / 180.0;
    } else {
        float extent = 0.0f;
        if (light.type == scene::LightType::Sphere) extent = light.radius;
        if (light.type == scene::LightType::Rect) extent = 0.5f * glm::length(glm::vec2(light.size.x, light.size.y));
        const glm::vec3 toLight = light.position - origin;
        const float lightDistance = glm::length(toLight);
        if (!(lightDistance > extent)) return true;
        axis = toLight / lightDistance;
        half = std::asin(double(extent) / double(lightDistance));
    }
    const double sphereHalf = std::asin(double(sphere.radius) / double(sphereDistance));
    const double cosAngle = std::clamp(double(glm::dot(axis, toSphere / sphereDistance)), -1.0, 1.0);
    return std::acos(cosAngle) <= half + sphereHalf + 2.0 * texelRadius + 1e-4;
}

} // namespace

EditSummary RelightPreview::applyChanges(const scene::Scene& edited, const scene::ChangeSet& changes,
                                         bool deferMovedObjects, bool useField) {
    ++m_revision;
    if (m_field) {
        if (useField && !deferMovedObjects && isFieldDrag(edited, changes)) return applyFieldDrag(edited);
        // The field's masks live in world axes about the object's centre: a translation keeps
        // them (also one taken the exact way), a rotation, scale or another mesh does not.
        bool dropField = structural(*m_scene, edited, changes);
        if (!dropField) {
            const scene::Object& was = m_scene->objects[m_field->object];
            const scene::Object& now = edited.objects[m_field->object];
            dropField = was.id != now.id || was.mesh != now.mesh || was.transform.rotationDeg != now.transform.rotationDeg ||
                        was.transform.scale != now.transform.scale;
        }
        settleFieldDrag(dropField);
    }
    EditSummary summary;
    m_touched.assign(m_points.size(), 0);
    if (structural(*m_scene, edited, changes)) {
        rebuildAll(edited);
        summary.kind = "structure";
        summary.factorsRebuilt = {"all"};
        summary.pointsTouched = m_points.size();
        return summary;
    }
    bool environment = false, camera = false, objectMaterial = false;
    std::vector<size_t> lights, objects;
    std::vector<uint32_t> materials;
    for (const scene::Invalidation& inv : changes.invalidations()) {
        switch (inv.factor) {
        case scene::FactorKind::Environment: environment = true; break;
        case scene::FactorKind::Camera: camera = true; break;
        case scene::FactorKind::Light: lights.push_back(indexOf(edited.lighting.lights, inv.id)); break;
        case scene::FactorKind::ObjectGeometry: objects.push_back(indexOf(edited.objects, inv.id)); break;
        case scene::FactorKind::ObjectMaterial: objectMaterial = true; break;
        case scene::FactorKind::MaterialBrdf:
            materials.push_back(uint32_t(indexOf(edited.materials, inv.id)));
            break;
        case scene::FactorKind::None: break;
        }
    }
    std::erase_if(lights, [&](size_t k) { return k >= edited.lighting.lights.size(); });
    std::erase_if(objects, [&](size_t j) { return j >= edited.objects.size(); });
    summary.kind = camera ? "camera"
                   : !objects.empty() || objectMaterial ? "object"
                   : !materials.empty()                 ? "material"
                   : !lights.empty()                    ? "light"
                   : environment                        ? "environment"
                                                        : "display";

    util::Timer timer;
    // Power-only edits: the image sums the cached terms with the new powers, nothing else.
    if (environment && m_scene->lighting.environment.image == edited.lighting.environment.image &&
        onlyScales(changes, {scene::EntityKind::Environment, scene::kInvalidId}, {"intensity", "tint"})) {
        environment = false;
        summary.factorsRebuilt.push_back("environment power");
    }
    std::erase_if(lights, [&](size_t k) {
        if (!onlyScales(changes, {scene::EntityKind::Light, edited.lighting.lights[k].id}, {"intensity", "color"}))
            return false;
        summary.factorsRebuilt.push_back("light power:" + edited.lighting.lights[k].name);
        return true;
    });
    // Colour and emission edits of a material whose f is linear or affine in its colour (or does
    // not read it): the terms are cached for white and black, so the image mixes in the new
    // colour, nothing per point (colour_use.h). The class does not depend on the colour.
    std::erase_if(materials, [&](uint32_t m) {
        if (m >= m_materials.size() || m >= edited.materials.size()) return false;
        const scene::EntityRef ref{scene::EntityKind::Material, edited.materials[m].id};
        const bool colourFree = m_materials[m].colourUse != ColourUse::Fixed;
        if (onlyScales(changes, ref, {"emission"})) {
            summary.factorsRebuilt.push_back("emission:" + edited.materials[m].name);
            return true;
        }
        if (!colourFree || !onlyScales(changes, ref, {"baseColor", "emission"})) return false;
        summary.factorsRebuilt.push_back("brdf colour:" + edited.materials[m].name);
        return true;
    });
    std::vector<BoundingSphere> oldBounds;
    for (size_t j : objects) oldBounds.push_back(m_occluders[j].bounds);
    m_scene = std::make_unique<scene::Scene>(edited);
    resolveMaterials();
    if (environment) {
        buildEnvironment();
        summary.factorsRebuilt.push_back("environment");
    }
    for (size_t k : lights) summary.factorsRebuilt.push_back("light:" + m_scene->lighting.lights[k].name);
    for (uint32_t m : materials) summary.factorsRebuilt.push_back("brdf:" + m_scene->materials[m].name);
    for (size_t j : objects) {
        m_occluders[j] = buildObjectOccluder(*m_scene, j, m_convexity);
        summary.factorsRebuilt.push_back("occlusion:" + m_scene->objects[j].name);
    }
    const bool recast = camera || objectMaterial || !objects.empty();
    std::vector<PreviewPoint> cast;
    if (recast) {
        m_bvh = scene::buildBvh(*m_scene);
        summary.factorsRebuilt.push_back("gbuffer");
        if (camera) {
            cast = castPreviewPoints(*m_scene, m_bvh, m_settings.width, m_settings.height, m_settings.threads);
        } else {
            // Only rays that meet a changed object's old or new bounding sphere can find another
            // hit; the others keep their point (the other objects did not move).
            std::vector<BoundingSphere> spheres = oldBounds;
            for (size_t j : objects) spheres.push_back(m_occluders[j].bounds);
            for (const scene::Invalidation& inv : changes.invalidations())
                if (inv.factor == scene::FactorKind::ObjectMaterial)
                    if (size_t j = indexOf(edited.objects, inv.id); j < m_occluders.size())
                        spheres.push_back(m_occluders[j].bounds);
            cast = recastNear(spheres);
        }
    }

    summary.sharedMs = timer.milliseconds();
    timer.restart();
    const bool anyDeferred = std::find(m_deferred.begin(), m_deferred.end(), uint8_t(1)) != m_deferred.end();
    // Power, colour and emission edits leave nothing per point: skip the pass over the points.
    if (!recast && !environment && lights.empty() && materials.empty() && objects.empty() &&
        (!anyDeferred || deferMovedObjects)) {
        summary.pointsMs = timer.milliseconds();
        return summary;
    }
    const TransferContext ctx = context();
    const CameraRays rays(m_scene->camera, m_settings.width, m_settings.height);
    std::vector<uint8_t> touched(m_points.size(), 0);
    util::parallelFor(m_points.size(), m_settings.threads, [&](size_t i) {
        PreviewPoint& p = m_points[i];
        PointState& s = m_states[i];
        for (size_t k : lights) updateCameraLight(k, i, rays);
        auto moved = [&](const PreviewPoint& q) {
            return q.hit && std::find(objects.begin(), objects.end(), size_t(q.object)) != objects.end();
        };
        if (deferMovedObjects && recast && moved(cast[i])) {
            // Its ray now meets the moved object: stale until an edit without deferral (its old
            // hit and state kept, consistent with each other). A surface the object uncovered
            // is rebuilt below as usual.
            m_deferred[i] = 1;
            touched[i] = 1;
            return;
        }
        if (m_deferred[i]) { // deferred earlier: from scratch, on its current camera hit
            m_deferred[i] = 0;
            touched[i] = 1;
            p = recast ? cast[i]
                       : castPreviewPoint(*m_scene, m_bvh, m_settings.width, m_settings.height,
                                          int(i % size_t(m_settings.width)), int(i / size_t(m_settings.width)));
            for (size_t k = 0; k < m_cameraLights.size(); ++k) updateCameraLight(k, i, rays);
            if (p.hit) {
                s = buildPointState(ctx, p);
            } else {
                s = PointState{};
                m_background[i] = environmentRadiance(m_scene->lighting.environment, -p.wo);
            }
            return;
        }
        if (recast && !(cast[i] == p)) {
            PreviewPoint sameMaterial = p;
            sameMaterial.material = cast[i].material;
            const bool onlyMaterial = p.hit && sameMaterial == cast[i];
            p = cast[i];
            touched[i] = 1;
            for (size_t k = 0; k < m_cameraLights.size(); ++k) updateCameraLight(k, i, rays);
            if (onlyMaterial) {
                updateTransferAndTerms(ctx, p, s);
            } else if (p.hit) {
                s = buildPointState(ctx, p);
            } else {
                s = PointState{};
                m_background[i] = environmentRadiance(m_scene->lighting.environment, -p.wo);
            }
            return;
        }
        if (!p.hit) {
            if (environment) {
                m_background[i] = environmentRadiance(m_scene->lighting.environment, -p.wo);
                touched[i] = 1;
            }
            return;
        }
        if (std::find(objects.begin(), objects.end(), size_t(p.object)) != objects.end()) {
            s = buildPointState(ctx, p); // its own object changed under it: Õ1 too
            touched[i] = 1;
            return;
        }
        bool transfer = std::find(materials.begin(), materials.end(), p.material) != materials.end();
        bool lightsToo = false; // a moved object may shadow a local light within its distance
        const glm::vec3 origin = rayOrigin(p);
        for (size_t n = 0; n < objects.size(); ++n) {
            const size_t j = objects[n];
            // The shadow region: texels above the horizon that the old or the new bounding cone
            // may cover (light shadow rays run in all of them; O_j in the lit ones).
            if (!anyOverlap(coneTexels(oldBounds[n], origin, m_dirs, s.above),
                            coneTexels(m_occluders[j].bounds, origin, m_dirs, s.above)))
                continue;
            touched[i] = 1;
            lightsToo = true;
            const std::vector<Occlusion> before = s.occlusions;
            updateOcclusion(ctx, p, s, uint32_t(j));
            const bool same = before.size() == s.occlusions.size() &&
                              std::equal(before.begin(), before.end(), s.occlusions.begin(),
                                         [](const Occlusion& a, const Occlusion& b) {
                                             return a.object == b.object && a.blocked == b.blocked;
                                         });
            transfer = transfer || !same;
        }
        if (transfer) {
            touched[i] = 1;
            updateTransferAndTerms(ctx, p, s);
            return;
        }
        if (environment) {
            updateEnvironmentTerms(ctx, s);
            touched[i] = 1;
        }
        if (lightsToo) {
            // O_j is unchanged here, so a light term can change only through its shadow rays
            // (cast toward local lights, in texels blocked at infinity), and only if the object's
            // old or new sphere can lie across them.
            for (size_t k = 0; k < s.lightTerms.size(); ++k) {
                const scene::Light& light = m_scene->lighting.lights[k];
                if (light.type == scene::LightType::Sun) continue; // no shadow rays: O factors only
                bool meets = false;
                for (size_t n = 0; n < objects.size() && !meets; ++n)
                    meets = lightConeMeets(light, origin, oldBounds[n], m_dirs.texelRadius()) ||
                            lightConeMeets(light, origin, m_occluders[objects[n]].bounds, m_dirs.texelRadius());
                if (meets) updateLightTerms(ctx, p, s, k);
            }
            return;
        }
        for (size_t k : lights) {
            updateLightTerms(ctx, p, s, k);
            touched[i] = 1;
        }
    });
    summary.pointsTouched = size_t(std::count(touched.begin(), touched.end(), uint8_t(1)));
    summary.pointsMs = timer.milliseconds();
    m_touched = std::move(touched);
    return summary;
}

std::vector<PreviewPoint> RelightPreview::recastNear(const std::vector<BoundingSphere>& spheres) const {
    std::vector<PreviewPoint> cast = m_points;
    const glm::vec3 eye = m_scene->camera.position;
    util::parallelFor(cast.size(), m_settings.threads, [&](size_t i) {
        const glm::vec3 dir = -cast[i].wo;
        for (const BoundingSphere& b : spheres) {
            const glm::vec3 oc = eye - b.centre;
            const float half = glm::dot(oc, dir), c = glm::dot(oc, oc) - b.radius * b.radius;
            if (b.radius >= 0.0f && (c <= 0.0f || (half <= 0.0f && half * half >= c))) {
                cast[i] = castPreviewPoint(*m_scene, m_bvh, m_settings.width, m_settings.height,
                                           int(i % size_t(m_settings.width)), int(i / size_t(m_settings.width)));
                return;
            }
        }
    });
    return cast;
}

} // namespace wavelit::relight
