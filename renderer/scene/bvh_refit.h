// Updating a BVH in place after objects moved (architecture.md §5.B "What an edit rebuilds"):
// the moved objects' world-space triangles are recomputed from their meshes and the node bounds
// are refitted bottom-up; the tree's topology and triangle order stay, so the arrays keep their
// sizes and both tracers traverse them unchanged (shaders/common/bvh.glsl needs nothing new).
// A refit is exact (every hit is found) but its boxes may overlap more than a fresh build's, so
// traversal can get slower after large moves; a full buildBvh restores the quality.
#pragma once

#include "scene/bvh.h"

#include <vector>

namespace wavelit::scene {

// Recomputes the triangles of scene.objects[i] for every i in `objectIndices` (transform and
// material index) and refits every node's bounds. Returns false, leaving `bvh` unusable, when
// the tree no longer matches the scene (an object's triangle count or mesh changed, an index is
// out of range, or a triangle became degenerate): the caller then builds anew.
bool refitObjects(Bvh& bvh, const Scene& scene, const std::vector<size_t>& objectIndices);

} // namespace wavelit::scene
