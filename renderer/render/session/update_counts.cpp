#include "render/session/update_counts.h"

#include <utility>
#include <vector>

namespace wavelit::render {

UpdateCounts& UpdateCounts::operator+=(const UpdateCounts& o) {
    bvhBuilds += o.bvhBuilds;
    bvhRefits += o.bvhRefits;
    geometryUploads += o.geometryUploads;
    lightUploads += o.lightUploads;
    materialUploads += o.materialUploads;
    envTexelUploads += o.envTexelUploads;
    samplerTableUploads += o.samplerTableUploads;
    paramUploads += o.paramUploads;
    samplerTableBuilds += o.samplerTableBuilds;
    samplerTablesTurned += o.samplerTablesTurned;
    return *this;
}

std::string describeUpdate(const UpdateCounts& c) {
    std::string rebuilt;
    auto add = [](std::string& s, const std::string& item) { s += (s.empty() ? "" : ", ") + item; };
    if (c.bvhBuilds)
        add(rebuilt, "bvh built " + std::to_string(c.bvhBuilds));
    if (c.bvhRefits)
        add(rebuilt, "bvh refit " + std::to_string(c.bvhRefits));
    if (c.samplerTableBuilds)
        add(rebuilt, std::to_string(c.samplerTableBuilds) + " sampler tables");
    if (c.samplerTablesTurned)
        add(rebuilt, "env tables turned");
    std::string uploaded;
    const std::vector<std::pair<int, const char*>> kinds = {
        {c.geometryUploads, "geometry"},   {c.lightUploads, "lights"},
        {c.materialUploads, "materials"},  {c.envTexelUploads, "env texels"},
        {c.samplerTableUploads, "sampler tables"}, {c.paramUploads, "params"}};
    for (const auto& [n, name] : kinds)
        if (n)
            add(uploaded, n == 1 ? std::string(name) : std::string(name) + " x" + std::to_string(n));
    if (rebuilt.empty() && uploaded.empty())
        return "nothing rebuilt or uploaded";
    std::string out;
    if (!rebuilt.empty())
        out = "rebuilt: " + rebuilt;
    if (!uploaded.empty())
        out += (out.empty() ? "" : "; ") + std::string("uploaded: ") + uploaded;
    return out;
}

} // namespace wavelit::render
