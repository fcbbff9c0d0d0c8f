#include "cli/light_mix.h"

#include "render/session/light_groups.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace wavelit::cli {
namespace {

using util::ErrorKind;
using util::makeError;

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, separator)) parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.push_back("");
    return parts;
}

util::Result<float> parseFactor(const std::string& text, const std::string& name) {
    size_t used = 0;
    float value = 0.0f;
    try {
        value = std::stof(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || !std::isfinite(value) || value < 0.0f)
        return makeError(ErrorKind::Usage, "",
                         "--weights: the weight of '" + name + "' must be a finite number >= 0 " +
                             "or r:g:b, got '" + text + "'");
    return value;
}

} // namespace

util::Result<MixWeights> parseMixWeights(const std::string& text) {
    MixWeights weights;
    if (text.empty()) return makeError(ErrorKind::Usage, "", "--weights needs name=value[,...]");
    for (const std::string& item : split(text, ',')) {
        const size_t eq = item.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
            return makeError(ErrorKind::Usage, "",
                             "--weights: expected name=value or name=r:g:b, got '" + item + "'");
        const std::string name = item.substr(0, eq);
        const std::vector<std::string> parts = split(item.substr(eq + 1), ':');
        if (parts.size() != 1 && parts.size() != 3)
            return makeError(ErrorKind::Usage, "",
                             "--weights: the weight of '" + name + "' must be one number or r:g:b, got '" +
                                 item.substr(eq + 1) + "'");
        glm::vec3 w;
        for (int c = 0; c < 3; ++c) {
            auto f = parseFactor(parts[parts.size() == 1 ? 0 : size_t(c)], name);
            if (!f) return f.error();
            w[c] = *f;
        }
        auto same = [&](const auto& p) { return p.first == name; };
        if (std::any_of(weights.begin(), weights.end(), same))
            return makeError(ErrorKind::Usage, "", "--weights names '" + name + "' twice");
        weights.emplace_back(name, w);
    }
    return weights;
}

util::Result<scene::LayeredImage> mixLayers(const scene::LayeredImage& image,
                                            const MixWeights& weights, const std::string& file) {
    if (image.layers.empty())
        return makeError(ErrorKind::Invalid, file,
                         "has no light-group layers (render it with --light-groups)");
    std::string unknown, known;
    for (const auto& [name, w] : weights) {
        auto has = [&](const scene::ExrLayerImage& l) { return l.name == name; };
        if (std::none_of(image.layers.begin(), image.layers.end(), has))
            unknown += (unknown.empty() ? "'" : ", '") + name + "'";
    }
    if (!unknown.empty()) {
        for (const scene::ExrLayerImage& l : image.layers)
            known += (known.empty() ? "" : ", ") + l.name;
        return makeError(ErrorKind::Invalid, file,
                         "no light group " + unknown + " (its groups: " + known + ")");
    }
    scene::LayeredImage out = image;
    std::vector<const util::ImageRGB*> layers;
    std::vector<glm::vec3> layerWeights;
    for (scene::ExrLayerImage& layer : out.layers) {
        glm::vec3 w(1.0f);
        for (const auto& [name, weight] : weights)
            if (name == layer.name) w = weight;
        for (glm::vec3& p : layer.image.pixels) p *= w; // the output's layers carry their weights
        layers.push_back(&layer.image);
        layerWeights.push_back(glm::vec3(1.0f)); // already applied
    }
    out.beauty = render::mixGroupLayers(layers, layerWeights);
    return out;
}

} // namespace wavelit::cli
