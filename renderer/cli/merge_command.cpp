// `wavelit-cli merge A.exr B.exr ... -o OUT.exr` (issue 17, docs/farm.md): merges renders of
// disjoint pass ranges of one scene with one set of settings (`render --passes FIRST:COUNT`)
// into the render of all their passes: each pixel is the sum over the parts of mean x pass count,
// over the total pass count, so the result equals a single render of those passes up to float
// summation order. The output is a rendered EXR like the parts (mean radiance, and attributes
// naming every pass it holds), so merged files merge again.
// Refused with exit 1 and a message naming the parts: a file that is not a Wavelit render, parts
// of different scenes (wavelit:sceneDigest) or settings (size, sampler, seed, bounces, tracer),
// and parts whose pass ranges overlap (a pass counted twice). Exit 2: bad usage.
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/partial_render.h"
#include "util/path_util.h"

#include <algorithm>
#include <cstdio>

namespace wavelit::cli {
namespace {

using util::ErrorKind;
using util::makeError;

std::string describe(const RenderPart& p) {
    return p.path + " (passes " + formatPassRanges(p.passes) + ")";
}

// Why `b` cannot be merged with `a`, or empty.
std::string mismatch(const RenderPart& a, const RenderPart& b) {
    if (a.identity.sceneDigest != b.identity.sceneDigest)
        return a.path + " and " + b.path + " are renders of different scenes (" +
               a.identity.scenePath + ", digest " + a.identity.sceneDigest + " vs " +
               b.identity.scenePath + ", digest " + b.identity.sceneDigest + ")";
    for (size_t i = 0; i < a.identity.settings.size(); ++i) {
        const auto& [key, value] = a.identity.settings[i];
        if (value != b.identity.settings[i].second)
            return a.path + " and " + b.path + " were rendered with different " + key + " (" +
                   value + " vs " + b.identity.settings[i].second + ")";
    }
    return {};
}

// Every pass in at most one part: sorted by first pass, a range must start after the one before.
std::string overlap(const std::vector<RenderPart>& parts) {
    struct Owned {
        PassRange range;
        const RenderPart* part;
    };
    std::vector<Owned> all;
    for (const RenderPart& p : parts)
        for (const PassRange& r : p.passes) all.push_back({r, &p});
    std::sort(all.begin(), all.end(),
              [](const Owned& a, const Owned& b) { return a.range.first < b.range.first; });
    for (size_t i = 1; i < all.size(); ++i) {
        const Owned &a = all[i - 1], &b = all[i];
        if (b.range.first < a.range.end()) {
            const int last = std::min(a.range.end(), b.range.end()) - 1;
            return describe(*a.part) + " and " + describe(*b.part) + " overlap in passes " +
                   std::to_string(b.range.first) + ".." + std::to_string(last) +
                   ": each pass may be in one part only";
        }
    }
    return {};
}

int run(const std::vector<std::string>& argv) {
    auto args = Args::parse(argv, {"-o"});
    if (!args) return reportError(args.error());
    const auto output = args->value("-o");
    if (!output) return reportError(makeError(ErrorKind::Usage, "", "merge needs -o OUT.exr"));
    if (util::lowerExtension(*output) != ".exr")
        return reportError(makeError(ErrorKind::Usage, *output, "merge output must end in .exr"));
    if (args->positional().empty())
        return reportError(makeError(ErrorKind::Usage, "", "merge needs at least one PART.exr"));

    std::vector<RenderPart> parts;
    for (const std::string& path : args->positional()) {
        auto part = readRenderPart(path);
        if (!part) return reportError(part.error());
        if (!parts.empty())
            if (std::string why = mismatch(parts.front(), *part); !why.empty())
                return reportError(makeError(ErrorKind::Invalid, "", why));
        parts.push_back(std::move(part).value());
    }
    if (std::string why = overlap(parts); !why.empty())
        return reportError(makeError(ErrorKind::Invalid, "", why));

    // Sums in double: mean x count gives each part's sum back (to float rounding, ~1e-7).
    const util::ImageRGB& first = parts.front().mean;
    std::vector<glm::dvec3> sum(first.pixels.size(), glm::dvec3(0.0));
    std::vector<PassRange> passes;
    int total = 0;
    for (const RenderPart& p : parts) {
        for (size_t i = 0; i < sum.size(); ++i)
            sum[i] += glm::dvec3(p.mean.pixels[i]) * double(p.passCount);
        passes.insert(passes.end(), p.passes.begin(), p.passes.end());
        total += p.passCount;
    }
    util::ImageRGB merged(first.width, first.height);
    for (size_t i = 0; i < sum.size(); ++i) merged.pixels[i] = glm::vec3(sum[i] / double(total));

    RenderIdentity identity = parts.front().identity;
    for (const RenderPart& p : parts)
        if (p.identity.device != identity.device) identity.device = "several devices";
    const std::string ranges = formatPassRanges(passes);
    if (auto ok = scene::writeExr(*output, merged, renderAttributes(identity, passes)); !ok)
        return reportError(ok.error());
    std::printf("wrote %s (%zu parts, passes %s: %d spp)\n", output->c_str(), parts.size(),
                ranges.c_str(), total);
    if (ranges.find(',') != std::string::npos)
        std::fprintf(stderr,
                     "note: passes %s leave gaps: an unbiased render of those passes, but no "
                     "single render of consecutive passes equals it\n",
                     ranges.c_str());
    return 0;
}

} // namespace

int runMerge(const std::vector<std::string>& args) {
    return run(args);
}

} // namespace wavelit::cli
