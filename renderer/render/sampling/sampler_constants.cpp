// The roulette constant of `mis`'s env shadow ray (sampler_constants.h: why it follows the env's
// concentration). One function for both tracers: the Vulkan one gets its float in the params block.
#include "render/sampling/sampler_constants.h"

#include <algorithm>

namespace wavelit::render {

float misEnvRoulette(double effectiveSolidAngle) {
    const double scale =
        std::clamp(effectiveSolidAngle / kMisEnvRouletteSolidAngle, kMisEnvRouletteMinScale, 1.0);
    return float(kMisEnvRoulette * scale);
}

} // namespace wavelit::render
