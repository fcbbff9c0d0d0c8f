// `wavelit-cli validate FILE` (architecture.md §6): loads a scene, lighting setup, mesh or image the way
// the renderer would. Exit 1 with the first problem when the file cannot be used; exit 0 with a
// one-line summary when it can. Unknown keys and unknown BRDFs are load errors (scene_io.h), so
// validate, `render` and the editor refuse the same files with the same message. What loading
// would sanitise (NaN/Inf/negative texels replaced by 0, zero-area triangles skipped) is printed as
// "warning:" lines on stderr and fails validation with exit 1: the renderer and editor load such
// files after the named repair, but a validator that passed them would let a file that does not
// mean what it says into a pipeline (a NaN texel renders as black). docs/file-formats.md lists
// every warning.
#include "cli/args.h"
#include "cli/commands.h"
#include "scene/image_io.h"
#include "scene/mesh_loader.h"
#include "scene/scene_io.h"
#include "util/path_util.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

namespace wavelit::cli {

namespace {

using util::ErrorKind;
using util::makeError;

// Smallest image side validate accepts: a 1-texel environment has no direction information and a
// 1x1 square is a degenerate (level-0) wavelet factor, so a 1-pixel side is almost surely a broken
// export.
constexpr int kMinImageSide = 2;

using util::lowerExtension;

std::string sceneSummary(const scene::Scene& s) {
    size_t triangles = 0;
    for (const auto& o : s.objects) triangles += o.mesh ? o.mesh->triangleCount() : 0;
    const auto& env = s.lighting.environment;
    return "scene '" + s.name + "': " + std::to_string(s.objects.size()) + " objects, " +
           std::to_string(triangles) + " triangles, " + std::to_string(s.materials.size()) + " materials, " +
           std::to_string(s.lighting.lights.size()) + " lights, environment " +
           (env.image ? std::to_string(env.image->width) + "x" + std::to_string(env.image->height) : "constant");
}

std::string lightingSummary(const scene::LightingSetup& l) {
    const auto& env = l.environment;
    return "lighting setup '" + l.name + "': " + std::to_string(l.lights.size()) + " lights, environment " +
           (env.image ? std::to_string(env.image->width) + "x" + std::to_string(env.image->height) : "constant");
}

// Returns the summary line, or the first problem.
util::Result<std::string> validate(const std::string& path, std::vector<std::string>& warnings) {
    const std::string ext = lowerExtension(path);
    if (ext == ".wlscene") {
        scene::LoadReport report;
        auto s = scene::loadScene(path, &report);
        warnings = report.warnings;
        if (!s) return s.error();
        return sceneSummary(*s);
    }
    if (ext == ".wllight") {
        scene::LoadReport report;
        auto l = scene::loadLightingSetup(path, &report);
        warnings = report.warnings;
        if (!l) return l.error();
        return lightingSummary(*l);
    }
    if (ext == ".exr" || ext == ".hdr" || ext == ".pic") {
        auto image = scene::loadImage(path);
        if (!image) return image.error();
        warnings = image->warnings;
        const int w = image->image.width, h = image->image.height;
        if (w < kMinImageSide || h < kMinImageSide)
            return makeError(ErrorKind::Invalid, path,
                             std::to_string(w) + "x" + std::to_string(h) + " image is too small (at least " +
                                 std::to_string(kMinImageSide) + "x" + std::to_string(kMinImageSide) + ")");
        return "image " + std::to_string(w) + "x" + std::to_string(h) + (w == h ? " (square)" : "");
    }
    if (scene::isMeshExtension(ext)) {
        auto mesh = scene::loadMesh(path, &warnings);
        if (!mesh) return mesh.error();
        return "mesh: " + std::to_string(mesh->positions.size()) + " vertices, " +
               std::to_string(mesh->triangleCount()) + " triangles";
    }
    return makeError(ErrorKind::Unsupported, path,
                     "unknown file type '" + ext + "' (expected .wlscene, .wllight, an image or a mesh)");
}

} // namespace

int runValidate(const std::vector<std::string>& argv) {
    auto args = Args::parse(argv, {}, {});
    if (!args) return reportError(args.error());
    if (args->positional().size() != 1)
        return reportError(makeError(ErrorKind::Usage, "", "usage: wavelit-cli validate FILE"));
    const std::string path = args->positional()[0];
    std::vector<std::string> warnings;
    auto summary = validate(path, warnings);
    if (!summary) return reportError(summary.error());
    // A warning from a referenced file (an env map of a lighting setup) is prefixed with the file
    // validated, so every line names what the user asked about.
    for (const auto& w : warnings)
        std::fprintf(stderr, "wavelit-cli: warning: %s%s\n", w.rfind(path, 0) == 0 ? "" : (path + ": ").c_str(), w.c_str());
    if (!warnings.empty()) {
        std::fprintf(stderr, "wavelit-cli: %s: invalid: %zu problem(s) that loading would repair (%s)\n",
                     path.c_str(), warnings.size(), summary->c_str());
        return 1;
    }
    std::printf("%s: ok: %s\n", path.c_str(), summary->c_str());
    return 0;
}

} // namespace wavelit::cli
