// `wavelit-cli extract-sun SCENE.wlscene|SETUP.wllight -o OUT.wllight` (issue 21, docs/lightmix.md
// "Extract sun"): writes the input's lighting setup with a `sun` light made from the environment's
// brightest compact region and that region masked out of the map (render/lights/extract_sun.h).
// The map file is untouched; OUT's environment path names the same map from OUT's folder.
// Exit 1: the input does not load, its environment has no map or no sun, or is masked already.
#include "cli/args.h"
#include "cli/commands.h"
#include "render/lights/extract_sun.h"
#include "scene/scene_io.h"
#include "util/path_util.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace wavelit::cli {

namespace fs = std::filesystem;

int runExtractSun(const std::vector<std::string>& argv) {
    using util::ErrorKind;
    using util::makeError;
    auto args = Args::parse(argv, {"-o"});
    if (!args) return reportError(args.error());
    if (args->positional().size() != 1)
        return reportError(makeError(ErrorKind::Usage, "", "extract-sun needs exactly one SCENE.wlscene or SETUP.wllight"));
    auto output = args->value("-o");
    if (!output || util::lowerExtension(*output) != ".wllight")
        return reportError(makeError(ErrorKind::Usage, "", "extract-sun needs -o OUT.wllight"));
    const std::string input = args->positional()[0];

    // The scene whose lighting is extracted, and the file its environment path is relative to.
    scene::Scene scene;
    std::string envBase = input;
    if (util::lowerExtension(input) == ".wllight") {
        auto setup = scene::loadLightingSetup(input);
        if (!setup) return reportError(setup.error());
        scene.lighting = std::move(setup).value();
    } else {
        auto loaded = scene::loadScene(input);
        if (!loaded) return reportError(loaded.error());
        scene = std::move(loaded).value();
        if (!scene.lightingPath.empty())
            envBase = (fs::path(input).parent_path() / scene.lightingPath).lexically_normal().string();
    }
    // Errors name the file that describes the environment (a scene's own setup file, if any).
    auto extracted = render::extractSun(scene, envBase);
    if (!extracted) return reportError(extracted.error());

    scene::LightingSetup setup = extracted->scene.lighting;
    if (!setup.environment.path.empty()) {
        const fs::path map = (fs::path(envBase).parent_path() / setup.environment.path).lexically_normal();
        setup.environment.path = fs::proximate(map, fs::absolute(*output).parent_path()).generic_string();
    }
    if (auto written = scene::saveLightingSetup(setup, *output); !written) return reportError(written.error());
    const scene::Light& sun = setup.lights.back();
    const glm::vec3 toSun = -sun.direction;
    const double peakAngle = std::acos(std::clamp(double(glm::dot(glm::dvec3(toSun), extracted->peakDirection)), -1.0, 1.0)) *
                             180.0 / 3.14159265358979323846;
    std::printf("wrote %s: light '%s' toward (%.4f, %.4f, %.4f), angular diameter %.3f deg, colour (%.3f, %.3f, %.3f), "
                "intensity %.4g W/m^2; %.3f deg from the map's peak; %.1f%% of the map's energy; mask radius %.3f deg\n",
                output->c_str(), sun.name.c_str(), toSun.x, toSun.y, toSun.z, sun.angularDiameterDeg, sun.color.r,
                sun.color.g, sun.color.b, sun.intensity, peakAngle, 100.0 * extracted->energyFraction,
                setup.environment.maskRadiusDeg);
    return 0;
}

} // namespace wavelit::cli
