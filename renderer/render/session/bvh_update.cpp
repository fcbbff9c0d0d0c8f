#include "render/session/bvh_update.h"

#include "scene/bvh_refit.h"

#include <algorithm>
#include <variant>

namespace wavelit::render {
namespace {

enum class BvhWork { None, Refit, Build };

// How much costlier than at its build a refitted tree may get (surface-area heuristic) before the
// next move rebuilds it: a drag across the scene stays fast to trace, small moves never rebuild.
constexpr float kMaxRefitCostGrowth = 1.5f;

// Object properties whose edit keeps the object's triangle count: its triangles are recomputed
// in place (transform, material index). A mesh edit changes the triangles themselves.
bool refittable(const std::string& property) {
    return property == "translation" || property == "rotation" || property == "scale" ||
           property == "material";
}

} // namespace

std::shared_ptr<const scene::Bvh> updateBvh(std::shared_ptr<const scene::Bvh> current,
                                            const scene::Scene& after,
                                            const scene::ChangeSet& changes, UpdateCounts& counts) {
    BvhWork work = BvhWork::None;
    std::vector<size_t> moved;
    for (const scene::Edit& edit : changes.edits()) {
        if (const auto* entity = std::get_if<scene::EntityEdit>(&edit)) {
            // Adding or removing an object or material shifts the indices the triangles carry.
            if (entity->ref().kind != scene::EntityKind::Light)
                work = BvhWork::Build;
            continue;
        }
        const auto& p = std::get<scene::PropertyEdit>(edit);
        if (p.entity.kind != scene::EntityKind::Object || p.property == "name")
            continue;
        if (!refittable(p.property)) {
            work = BvhWork::Build;
            continue;
        }
        for (size_t i = 0; i < after.objects.size(); ++i)
            if (after.objects[i].id == p.entity.id && std::find(moved.begin(), moved.end(), i) == moved.end())
                moved.push_back(i);
        work = std::max(work, BvhWork::Refit);
    }
    if (work == BvhWork::None && current)
        return current;
    if (work == BvhWork::Refit && current && !moved.empty()) {
        auto refitted = std::make_shared<scene::Bvh>(*current);
        // A refit keeps the topology of the last build; once moves have made the boxes overlap
        // so much that a ray costs kMaxRefitCostGrowth times what it did, build afresh.
        if (scene::refitObjects(*refitted, after, moved) &&
            scene::bvhSahCost(*refitted) <= kMaxRefitCostGrowth * refitted->builtSahCost) {
            ++counts.bvhRefits;
            return refitted;
        }
    }
    ++counts.bvhBuilds;
    return std::make_shared<const scene::Bvh>(scene::buildBvh(after));
}

} // namespace wavelit::render
