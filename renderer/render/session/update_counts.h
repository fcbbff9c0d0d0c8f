// What one scene update cost (architecture.md §5.B "What an edit rebuilds"): BVH builds and refits
// and the buffers sent to the device, per kind. The session counts the BVH work, the integrator
// the uploads; the render report and the editor's status label show the last update's counts so
// that an edit which re-sends more than it changed is visible, and tests assert them per edit kind.
#pragma once

#include <string>

namespace wavelit::render {

struct UpdateCounts {
    int bvhBuilds = 0;          // full binned-SAH builds (scene::buildBvh)
    int bvhRefits = 0;          // in-place updates of moved objects (scene::refitObjects)
    int geometryUploads = 0;    // BVH nodes + triangles
    int lightUploads = 0;       // analytic lights
    int materialUploads = 0;    // material parameters
    int envTexelUploads = 0;    // environment map texels
    int samplerTableUploads = 0; // direction samplers' tables (env table, materials, words)
    int paramUploads = 0;       // camera and the other scene parameters (one small block)
    int samplerTableBuilds = 0; // environment + material tables built (not reused) by the update
    int samplerTablesTurned = 0; // env tables turned to a new rotation instead (no rebuild)

    UpdateCounts& operator+=(const UpdateCounts& o);
    bool operator==(const UpdateCounts&) const = default;
};

// "rebuilt: bvh refit 1; uploaded: geometry" — what the last update rebuilt and uploaded, in a
// line for the status label and the report; "nothing rebuilt or uploaded" when all are zero.
std::string describeUpdate(const UpdateCounts& counts);

} // namespace wavelit::render
