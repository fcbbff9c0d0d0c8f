// The BVH after a change set (architecture.md §5.B "What an edit rebuilds"): the same BVH when the
// edits touch no geometry (lights, materials, environment, camera), the current one refitted for
// objects that moved or changed material (scene/bvh_refit.h), and a full build only when the
// object or material lists changed or a mesh was replaced (indices and triangle counts move).
#pragma once

#include "render/session/update_counts.h"
#include "scene/bvh.h"
#include "scene/change_set.h"
#include "scene/scene.h"

#include <memory>

namespace wavelit::render {

// `current` is the BVH of the scene before `changes`; `after` the scene after them. Adds the
// work done (bvhBuilds or bvhRefits) to `counts`.
std::shared_ptr<const scene::Bvh> updateBvh(std::shared_ptr<const scene::Bvh> current,
                                            const scene::Scene& after,
                                            const scene::ChangeSet& changes, UpdateCounts& counts);

} // namespace wavelit::render
