// The sphere grid a scene needs (architecture.md §7: model only what a scene needs, say why):
// 32² unless a material in use has a glossy lobe narrower than half a 32² texel, then 64², and
// 128² for one narrower than half a 64² texel (GGX roughness below ~0.13). A chrome mirror seen
// through coarse texels is a blur of what it reflects: docs/relighting.md §7 measured relRMSE on
// glossy_sphere (r = 0.1) 0.81 at 32², 0.18 at 64², 0.14 at 128² (the target is 0.15), at 2.8,
// 4.5 and 9 KB a point. Never finer (the sparse T's 16-bit indices stop at 128²).
#pragma once

#include "scene/scene.h"

#include <string>

namespace wavelit::relight {

struct SphereLevelChoice {
    int level = 5;
    std::string reason;
};

SphereLevelChoice chooseSphereLevel(const scene::Scene& scene);

} // namespace wavelit::relight
