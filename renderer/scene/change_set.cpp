#include "scene/change_set.h"

#include <algorithm>

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

namespace {

template <typename E> std::vector<E>& listOf(Scene& scene);
template <> std::vector<Material>& listOf<Material>(Scene& s) { return s.materials; }
template <> std::vector<Object>& listOf<Object>(Scene& s) { return s.objects; }
template <> std::vector<Light>& listOf<Light>(Scene& s) { return s.lighting.lights; }

template <typename E> EntityKind kindOf();
template <> EntityKind kindOf<Material>() { return EntityKind::Material; }
template <> EntityKind kindOf<Object>() { return EntityKind::Object; }
template <> EntityKind kindOf<Light>() { return EntityKind::Light; }

util::Status applyEntity(Scene& scene, const EntityEdit& edit) {
    return std::visit(
        [&](const auto& entity) -> util::Status {
            using E = std::decay_t<decltype(entity)>;
            auto& list = listOf<E>(scene);
            auto it = std::find_if(list.begin(), list.end(), [&](const E& e) { return e.id == entity.id; });
            const char* kind = entityKindName(kindOf<E>());
            if (edit.add) {
                if (it != list.end())
                    return makeError(ErrorKind::Invalid, "", std::string(kind) + " id " + std::to_string(entity.id) + " already exists");
                list.insert(list.begin() + std::ptrdiff_t(std::min(edit.index, list.size())), entity);
            } else {
                if (it == list.end())
                    return makeError(ErrorKind::NotFound, "", std::string(kind) + " " + std::to_string(entity.id) + " not found");
                list.erase(it);
            }
            return util::okStatus();
        },
        edit.entity);
}

Invalidation entityInvalidation(const EntityEdit& edit) {
    const EntityRef ref = edit.ref();
    switch (ref.kind) {
    case EntityKind::Object: return {FactorKind::ObjectGeometry, ref.id};
    case EntityKind::Light: return {FactorKind::Light, ref.id};
    default: return {FactorKind::MaterialBrdf, ref.id};
    }
}

template <typename E> void recordAdd(std::vector<Edit>& edits, const Scene& scene, E entity) {
    if (entity.id == kInvalidId) entity.id = scene.nextId();
    const size_t index = listOf<E>(const_cast<Scene&>(scene)).size();
    edits.push_back(EntityEdit{true, index, std::move(entity)});
}

} // namespace

EntityRef EntityEdit::ref() const {
    return std::visit(
        [](const auto& e) {
            using E = std::decay_t<decltype(e)>;
            return EntityRef{kindOf<E>(), e.id};
        },
        entity);
}

util::Status ChangeSet::setProperty(const Scene& scene, EntityRef ref, const std::string& name, PropertyValue value) {
    auto old = getProperty(scene, ref, name);
    if (!old) return old.error();
    if (auto s = checkValue(*findProperty(ref.kind, name), value); !s) return s;
    m_edits.push_back(PropertyEdit{ref, name, std::move(old).value(), std::move(value)});
    return util::okStatus();
}

void ChangeSet::addMaterial(const Scene& scene, Material m) { recordAdd(m_edits, scene, std::move(m)); }
void ChangeSet::addObject(const Scene& scene, Object o) { recordAdd(m_edits, scene, std::move(o)); }
void ChangeSet::addLight(const Scene& scene, Light l) { recordAdd(m_edits, scene, std::move(l)); }

util::Status ChangeSet::removeEntity(const Scene& scene, EntityRef ref) {
    auto capture = [&](const auto& list) -> util::Status {
        for (size_t i = 0; i < list.size(); ++i)
            if (list[i].id == ref.id) {
                m_edits.push_back(EntityEdit{false, i, list[i]});
                return util::okStatus();
            }
        return makeError(ErrorKind::NotFound, "", std::string(entityKindName(ref.kind)) + " " + std::to_string(ref.id) + " not found");
    };
    switch (ref.kind) {
    case EntityKind::Material: return capture(scene.materials);
    case EntityKind::Object: return capture(scene.objects);
    case EntityKind::Light: return capture(scene.lighting.lights);
    default: return makeError(ErrorKind::Invalid, "", std::string("cannot remove the ") + entityKindName(ref.kind));
    }
}

util::Status ChangeSet::apply(Scene& scene) const {
    // Edits are validated as they go; on failure the copy is dropped so the scene is untouched.
    Scene work = scene;
    for (const Edit& e : m_edits) {
        util::Status s = std::holds_alternative<PropertyEdit>(e)
                             ? wavelit::scene::setProperty(work, std::get<PropertyEdit>(e).entity,
                                                           std::get<PropertyEdit>(e).property,
                                                           std::get<PropertyEdit>(e).newValue)
                             : applyEntity(work, std::get<EntityEdit>(e));
        if (!s) return s;
    }
    scene = std::move(work);
    return util::okStatus();
}

ChangeSet ChangeSet::inverted() const {
    ChangeSet out;
    for (auto it = m_edits.rbegin(); it != m_edits.rend(); ++it) {
        if (const auto* p = std::get_if<PropertyEdit>(&*it)) {
            out.m_edits.push_back(PropertyEdit{p->entity, p->property, p->newValue, p->oldValue});
        } else {
            EntityEdit e = std::get<EntityEdit>(*it);
            e.add = !e.add;
            out.m_edits.push_back(std::move(e));
        }
    }
    return out;
}

void ChangeSet::merge(const ChangeSet& newer) {
    for (const Edit& e : newer.m_edits) {
        if (const auto* p = std::get_if<PropertyEdit>(&e)) {
            // Only coalesce with the last edit touching anything of this entity, so an add/remove
            // in between keeps its order.
            auto last = std::find_if(m_edits.rbegin(), m_edits.rend(), [&](const Edit& x) {
                if (const auto* q = std::get_if<PropertyEdit>(&x)) return q->entity == p->entity && q->property == p->property;
                return std::get<EntityEdit>(x).ref() == p->entity;
            });
            if (last != m_edits.rend() && std::holds_alternative<PropertyEdit>(*last)) {
                std::get<PropertyEdit>(*last).newValue = p->newValue;
                continue;
            }
        }
        m_edits.push_back(e);
    }
}

std::vector<Invalidation> ChangeSet::invalidations() const {
    std::vector<Invalidation> out;
    for (const Edit& e : m_edits) {
        if (const auto* p = std::get_if<PropertyEdit>(&e))
            out.push_back(invalidationFor(*findProperty(p->entity.kind, p->property), p->entity));
        else
            out.push_back(entityInvalidation(std::get<EntityEdit>(e)));
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    out.erase(std::remove(out.begin(), out.end(), Invalidation{}), out.end());
    return out;
}

ChangeKind ChangeSet::changeKind() const {
    ChangeKind kind = ChangeKind::Display;
    for (const Edit& e : m_edits) {
        ChangeKind k = ChangeKind::Restart;
        if (const auto* p = std::get_if<PropertyEdit>(&e))
            k = findProperty(p->entity.kind, p->property)->change;
        else if (std::get<EntityEdit>(e).ref().kind == EntityKind::Object)
            k = ChangeKind::Rebuild;
        kind = std::max(kind, k);
    }
    return kind;
}

} // namespace wavelit::scene
