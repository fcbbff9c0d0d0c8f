// The registry of BRDF plugins: one line per plugin. Plugins do not self-register through static
// constructors because wavelit_plugins is a static library: the linker drops an object file no
// one references, and its registration with it. Listing them here references every plugin.
#include "plugins/brdf.h"

#include <array>

namespace wavelit::plugins {

// Defined in each plugin's .cpp.
const Brdf& lambertBrdf();
const Brdf& ggxBrdf();

namespace {
const std::array<const Brdf*, 2>& registry() {
    static const std::array<const Brdf*, 2> kAll{&lambertBrdf(), &ggxBrdf()};
    return kAll;
}
} // namespace

const Brdf* findBrdf(std::string_view name) {
    for (const Brdf* b : registry())
        if (name == b->name()) return b;
    return nullptr;
}

std::vector<std::string> brdfNames() {
    std::vector<std::string> names;
    for (const Brdf* b : registry()) names.emplace_back(b->name());
    return names;
}

} // namespace wavelit::plugins
