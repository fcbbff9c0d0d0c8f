#include "cli/partial_render.h"

#include "scene/scene_digest.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cstdio>

namespace wavelit::cli {

using util::ErrorKind;
using util::makeError;

namespace {

// The attribute set's version: a reader refuses files without it (not written by Wavelit).
constexpr const char* kVersionKey = "wavelit:render";
constexpr const char* kVersion = "1";

bool parseInt(const std::string& text, long long& out) {
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && ptr == text.data() + text.size();
}

const char* tracerOf(const std::string& deviceName) {
    return deviceName.rfind("CPU", 0) == 0 ? "cpu" : "vulkan";
}

// The settings every part of one render shares (RenderIdentity::settings), by attribute name.
constexpr const char* kSettingKeys[] = {"width", "height", "sampler", "seed", "bounces", "tracer"};

} // namespace

util::Result<PassRange> parsePassRange(const std::string& flag, const std::string& text,
                                       int maxCount) {
    const size_t colon = text.find(':');
    long long first = -1, count = -1;
    if (colon == std::string::npos || !parseInt(text.substr(0, colon), first) ||
        !parseInt(text.substr(colon + 1), count))
        return makeError(ErrorKind::Usage, "", flag + ": '" + text + "' is not FIRST:COUNT");
    if (first < 0 || count < 1 || count > maxCount || first + count > INT_MAX)
        return makeError(ErrorKind::Usage, "",
                         flag + ": '" + text + "' needs FIRST >= 0 and 1 <= COUNT <= " +
                             std::to_string(maxCount) + " (and FIRST + COUNT <= " +
                             std::to_string(INT_MAX) + ")");
    return PassRange{int(first), int(count)};
}

PassRange shareOfPasses(PassRange all, int rank, int ranks) {
    const int base = all.count / ranks, extra = all.count % ranks;
    return PassRange{all.first + rank * base + std::min(rank, extra),
                     base + (rank < extra ? 1 : 0)};
}

std::string formatPassRanges(std::vector<PassRange> ranges) {
    std::sort(ranges.begin(), ranges.end(),
              [](const PassRange& a, const PassRange& b) { return a.first < b.first; });
    std::vector<PassRange> joined;
    for (const PassRange& r : ranges) {
        if (!joined.empty() && joined.back().end() == r.first)
            joined.back().count += r.count;
        else
            joined.push_back(r);
    }
    std::string text;
    for (const PassRange& r : joined) {
        if (!text.empty()) text += ',';
        text += std::to_string(r.first);
        text += ':';
        text += std::to_string(r.count);
    }
    return text;
}

RenderIdentity renderIdentity(const scene::Scene& scene, const std::string& scenePath,
                              const render::RenderOptions& options, const std::string& deviceName) {
    RenderIdentity id;
    id.scenePath = scenePath;
    id.sceneDigest = scene::sceneDigest(scene);
    id.settings = {{"width", std::to_string(options.width)},
                   {"height", std::to_string(options.height)},
                   {"sampler", render::samplerKindName(options.sampler)},
                   {"seed", std::to_string(options.seed)},
                   {"bounces", std::to_string(options.bounces)},
                   {"tracer", tracerOf(deviceName)}};
    id.device = deviceName;
    return id;
}

scene::ExrAttributes renderAttributes(const RenderIdentity& identity,
                                      const std::vector<PassRange>& passes) {
    scene::ExrAttributes a{{kVersionKey, kVersion},
                           {"wavelit:scene", identity.scenePath},
                           {"wavelit:sceneDigest", identity.sceneDigest},
                           {"wavelit:device", identity.device}};
    for (const auto& [key, value] : identity.settings) a["wavelit:" + key] = value;
    int count = 0, first = INT_MAX;
    for (const PassRange& r : passes) {
        count += r.count;
        first = std::min(first, r.first);
    }
    a["wavelit:passes"] = formatPassRanges(passes);
    a["wavelit:passCount"] = std::to_string(count);
    a["wavelit:firstPass"] = std::to_string(passes.empty() ? 0 : first);
    return a;
}

util::Result<RenderPart> readRenderPart(const std::string& path) {
    auto attributes = scene::readExrAttributes(path);
    if (!attributes) return attributes.error();
    const scene::ExrAttributes& a = *attributes;
    auto bad = [&](const std::string& why) { return makeError(ErrorKind::Format, path, why); };
    auto find = [&](const std::string& key) -> const std::string* {
        auto it = a.find("wavelit:" + key);
        return it == a.end() ? nullptr : &it->second;
    };
    const std::string* version = find("render");
    if (!version)
        return bad("not a render written by wavelit-cli render or merge (no wavelit:render "
                   "attribute; docs/file-formats.md \"Rendered EXR\")");
    if (*version != kVersion)
        return makeError(ErrorKind::Unsupported, path,
                         "wavelit:render version " + *version + ", this build reads " + kVersion);
    RenderPart part;
    part.path = path;
    for (const char* key : {"scene", "sceneDigest", "device", "passes", "passCount", "firstPass"})
        if (!find(key)) return bad(std::string("wavelit:") + key + " attribute missing");
    part.identity.scenePath = *find("scene");
    part.identity.sceneDigest = *find("sceneDigest");
    part.identity.device = *find("device");
    for (const char* key : kSettingKeys) {
        const std::string* value = find(key);
        if (!value) return bad(std::string("wavelit:") + key + " attribute missing");
        part.identity.settings.emplace_back(key, *value);
    }
    // The pass list: sorted, disjoint, summing to passCount, starting at firstPass.
    const std::string& list = *find("passes");
    for (size_t at = 0; at <= list.size();) {
        const size_t comma = std::min(list.find(',', at), list.size());
        auto range = parsePassRange("wavelit:passes", list.substr(at, comma - at), INT_MAX);
        if (!range) return bad(range.error().message());
        if (!part.passes.empty() && range->first < part.passes.back().end())
            return bad("wavelit:passes '" + list + "' is not sorted and disjoint");
        part.passes.push_back(*range);
        part.passCount += range->count;
        at = comma + 1;
    }
    if (std::to_string(part.passCount) != *find("passCount"))
        return bad("wavelit:passCount " + *find("passCount") +
                   " does not match wavelit:passes " + list);
    if (std::to_string(part.passes.front().first) != *find("firstPass"))
        return bad("wavelit:firstPass " + *find("firstPass") +
                   " does not match wavelit:passes " + list);
    scene::ImageLoadOptions load;
    // A render's radiance is finite and non-negative: a texel that is not is damage, refused.
    load.sanitize = false;
    auto image = scene::loadImage(path, load);
    if (!image) return image.error();
    part.mean = std::move(image->image);
    const std::string size =
        std::to_string(part.mean.width) + "x" + std::to_string(part.mean.height);
    if (size != *find("width") + "x" + *find("height"))
        return bad("the image is " + size + ", its attributes say " + *find("width") + "x" +
                   *find("height"));
    return part;
}

} // namespace wavelit::cli
