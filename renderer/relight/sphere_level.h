// The sphere grid a scene needs (architecture.md §7: model only what a scene needs, say why):
// 32² unless a material in use has a glossy lobe narrower than half a 32² texel, then 64² (a
// chrome mirror seen through 6° texels is a blur: docs/relighting.md §7 measured relRMSE 0.81 at
// 32² and 0.19 at 64² on glossy_sphere). Never finer: 64² with K = 128 is 3.5 KB a point.
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
