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
    char text[240];
    // The finest grid whose half texel is still wider than the lobe, from 32^2 up to 128^2.
    c.level = 5;
    while (c.level < 7 && 2.0 * narrowest < TexelDirections(c.level).texelRadius()) ++c.level;
    const int side = 1 << c.level;
    if (c.level == 5)
        std::snprintf(text, sizeof text, "32^2: no lobe in use is narrower than half a texel (%.3f rad)",
                      TexelDirections(5).texelRadius());
    else
        std::snprintf(text, sizeof text,
                      "%d^2: material '%s' has a lobe of half-width %.3f rad, under half a %d^2 texel (%.3f rad)",
                      side, which.c_str(), narrowest, side / 2, TexelDirections(c.level - 1).texelRadius());
    c.reason = text;
    return c;
}

} // namespace wavelit::relight
