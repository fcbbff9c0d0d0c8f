// Renders as parts of a longer render (issue 17, docs/farm.md): the pass ranges a part holds and
// the "wavelit:*" header attributes every EXR that `render` or `merge` writes carries
// (docs/file-formats.md "Rendered EXR"), read back and checked by `merge`.
//
// The pixels of such a file are the mean radiance over its passes, like any render; the sum of a
// pixel's samples is that mean times wavelit:passCount. A pass's random numbers depend only on
// (seed, pixel, pass index) (docs/estimator.md "Random numbers"), so parts of disjoint pass ranges
// of one scene and one set of settings add up to the render of their union.
#pragma once

#include "render/session/render_options.h"
#include "scene/image_io.h"
#include "scene/scene.h"
#include "util/image.h"
#include "util/result.h"

#include <string>
#include <utility>
#include <vector>

namespace wavelit::cli {

// Passes first, first + 1, ..., first + count - 1 of the progressive sequence.
struct PassRange {
    int first = 0;
    int count = 0;
    int end() const { return first + count; }
};

// "FIRST:COUNT" (FIRST >= 0, 1 <= COUNT <= maxCount, FIRST + COUNT within int); a Usage error
// naming `flag` otherwise.
util::Result<PassRange> parsePassRange(const std::string& flag, const std::string& text,
                                       int maxCount);

// Rank `rank` of `ranks`' contiguous share of `all`: the first count % ranks ranks take one pass
// more. Empty when there are more ranks than passes.
PassRange shareOfPasses(PassRange all, int rank, int ranks);

// "0:3,5:2": ranges sorted by first pass, adjacent ones joined.
std::string formatPassRanges(std::vector<PassRange> ranges);

// What a render is of, and how: merge refuses parts whose identities differ.
struct RenderIdentity {
    std::string scenePath;   // as given to `render`: information only, never compared
    std::string sceneDigest; // scene::sceneDigest: compared
    // Compared, in this order: width, height, sampler, seed, bounces, tracer (cpu|vulkan).
    std::vector<std::pair<std::string, std::string>> settings;
    std::string device; // the device's name: information only
};

// The identity of a render of `scene` with `options` on the device `deviceName` (a name that
// starts with "CPU" is the CPU reference tracer, any other a Vulkan device).
RenderIdentity renderIdentity(const scene::Scene& scene, const std::string& scenePath,
                              const render::RenderOptions& options, const std::string& deviceName);

// The header attributes of a render (or merge) of `passes` with that identity.
scene::ExrAttributes renderAttributes(const RenderIdentity& identity,
                                      const std::vector<PassRange>& passes);

// A rendered EXR read back: its identity, passes and mean image.
struct RenderPart {
    std::string path;
    RenderIdentity identity;
    std::vector<PassRange> passes; // sorted, disjoint
    int passCount = 0;
    util::ImageRGB mean;
};

// Reads `path` and checks its attributes against each other and the image (size, pass count).
// Errors name the file: not an EXR, not written by `render`/`merge`, or inconsistent.
util::Result<RenderPart> readRenderPart(const std::string& path);

} // namespace wavelit::cli
