#include "relight/sphere_level.h"

#include "relight/texel_directions.h"
#include "plugins/brdf.h"

#include <cstdio>
#include <limits>

namespace wavelit::relight {

SphereLevelChoice chooseSphereLevel(const scene::Scene& scene) {
    double narrowest = std::numeric_limits<double>::infinity();
    std::string which;
    for (const scene::Material& m : scene.materials) {
        bool used = false;
        for (const scene::Object& o : scene.objects) used = used || o.materialId == m.id;
        const plugins::Brdf* brdf = plugins::findBrdf(m.brdf);
        if (!used || !brdf || brdf->lobeAxis() != plugins::BrdfLobeAxis::Mirror) continue;
        const double half = brdf->lobeWidth({m.baseColor, m.roughness}).halfWidth;
        if (half < narrowest) {
            narrowest = half;
            which = m.name;
        }
    }
    SphereLevelChoice c;
    const double texel = TexelDirections(5).texelRadius();
    char text[200];
    if (2.0 * narrowest < texel) {
        c.level = 6;
        std::snprintf(text, sizeof text, "64^2: material '%s' has a lobe of half-width %.3f rad, under half a 32^2 texel (%.3f rad)",
                      which.c_str(), narrowest, texel);
    } else {
        c.level = 5;
        std::snprintf(text, sizeof text, "32^2: no lobe in use is narrower than half a texel (%.3f rad)", texel);
    }
    c.reason = text;
    return c;
}

} // namespace wavelit::relight
