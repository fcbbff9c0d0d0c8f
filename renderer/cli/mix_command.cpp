// `wavelit-cli mix IN.exr -o OUT.exr|png --weights sun=2,environment=0.5[,name=r:g:b]`
// (issue 21, docs/lightmix.md): recombines the light-group layers of a `render --light-groups`
// EXR with new weights (light_mix.h) without rendering again. An EXR output keeps the weighted
// layers (so it mixes again) and the input's attributes plus "wavelit:mixWeights"; a PNG holds the
// beauty after the display transform at --exposure EV (default 0). It prints how long the
// recombination took (the work an editor remix does per frame, before tone mapping). Exit 1: the input is unreadable or has no layers, or a weight names a
// group the file does not have (the message names them); exit 2: bad usage.
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/light_mix.h"
#include "scene/exr_layers.h"
#include "scene/image_io.h"
#include "util/path_util.h"
#include "util/timer.h"

#include <cstdio>
#include <sstream>

namespace wavelit::cli {

int runMix(const std::vector<std::string>& argv) {
    using util::ErrorKind;
    using util::makeError;
    auto args = Args::parse(argv, {"-o", "--weights", "--exposure"});
    if (!args) return reportError(args.error());
    if (args->positional().size() != 1)
        return reportError(makeError(ErrorKind::Usage, "", "mix needs exactly one IN.exr"));
    auto output = args->value("-o");
    if (!output) return reportError(makeError(ErrorKind::Usage, "", "mix needs -o OUT.exr|png"));
    const std::string ext = util::lowerExtension(*output);
    if (ext != ".exr" && ext != ".png")
        return reportError(makeError(ErrorKind::Usage, *output, "output must end in .exr or .png"));
    auto weightsText = args->value("--weights");
    if (!weightsText)
        return reportError(makeError(ErrorKind::Usage, "", "mix needs --weights name=value[,...]"));
    auto weights = parseMixWeights(*weightsText);
    if (!weights) return reportError(weights.error());
    auto exposure = args->doubleValue("--exposure", 0.0, -30.0, 30.0);
    if (!exposure) return reportError(exposure.error());

    const std::string input = args->positional()[0];
    auto image = scene::readExrLayers(input);
    if (!image) return reportError(image.error());
    util::Timer timer;
    auto mixed = mixLayers(*image, *weights, input);
    const double mixMs = timer.milliseconds();
    if (!mixed) return reportError(mixed.error());
    std::ostringstream applied;
    for (const auto& [name, w] : *weights)
        applied << (applied.tellp() > 0 ? "," : "") << name << "=" << w.r << ":" << w.g << ":" << w.b;
    mixed->attributes["wavelit:mixWeights"] = applied.str();
    auto written = ext == ".exr" ? scene::writeExrLayers(*output, *mixed)
                                 : scene::writePng(*output, mixed->beauty, float(*exposure));
    if (!written) return reportError(written.error());
    std::printf("wrote %s (%zu light groups, %zu reweighted; %dx%d mixed in %.2f ms)\n",
                output->c_str(), mixed->layers.size(), weights->size(), mixed->beauty.width,
                mixed->beauty.height, mixMs);
    return 0;
}

} // namespace wavelit::cli
