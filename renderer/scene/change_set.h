// Edits as change sets (architecture.md §9 "Threads"; architecture.md §5): the undo stack's commands and what the
// render thread drains between passes. A change set is a list of edits — a property's old and new
// value, or an entity added/removed with its full state and position — so it can be applied,
// inverted (undo) and merged (newest value per property wins, the first old value is kept, so the
// merged set still inverts to the state before the first edit). invalidations() names the cached
// factors to rebuild; changeKind() what the edit costs (display / restart / rebuild).
#pragma once

#include "scene/property_registry.h"
#include "scene/scene.h"
#include "util/result.h"

#include <string>
#include <variant>
#include <vector>

namespace wavelit::scene {

struct PropertyEdit {
    EntityRef entity;
    std::string property;
    PropertyValue oldValue;
    PropertyValue newValue;
};

// An entity added (or, inverted, removed) at `index` in its list.
struct EntityEdit {
    bool add = true;
    size_t index = 0;
    std::variant<Material, Object, Light> entity;
    EntityRef ref() const;
};

using Edit = std::variant<PropertyEdit, EntityEdit>;

class ChangeSet {
public:
    // Records setting a property; the old value is read from `scene` (which is not modified).
    util::Status setProperty(const Scene& scene, EntityRef ref, const std::string& name, PropertyValue value);
    // Records adding an entity at the end of its list / removing one (its state is captured).
    void addMaterial(const Scene& scene, Material material);
    void addObject(const Scene& scene, Object object);
    void addLight(const Scene& scene, Light light);
    util::Status removeEntity(const Scene& scene, EntityRef ref);
    // Records an edit whose old and new values are already known (an undo command's step).
    void add(Edit edit) { m_edits.push_back(std::move(edit)); }

    // Applies the edits in order. On failure the scene is left as it was.
    util::Status apply(Scene& scene) const;
    ChangeSet inverted() const;
    // Appends `newer`; for a property edited in both, one edit remains with this set's old value
    // and `newer`'s new value (the render thread's queue: newest value per property wins).
    void merge(const ChangeSet& newer);

    std::vector<Invalidation> invalidations() const; // sorted, unique
    ChangeKind changeKind() const;                    // the most expensive edit's kind
    const std::vector<Edit>& edits() const { return m_edits; }
    bool empty() const { return m_edits.empty(); }

private:
    std::vector<Edit> m_edits;
};

} // namespace wavelit::scene
