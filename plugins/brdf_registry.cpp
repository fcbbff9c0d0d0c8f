// The registry of BRDF plugins: one line per plugin. Plugins do not self-register through static
// constructors because wavelit_plugins is a static library: the linker drops an object file no
// one references, and its registration with it. Listing them here references every plugin.
// A plugin's position is its GPU type code, so the order is part of the GPU contract only within
// one run (the dispatch is generated from the same list at pipeline creation).
#include "plugins/brdf.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace wavelit::plugins {

// Defined in each plugin's .cpp.
const Brdf& lambertBrdf();
const Brdf& ggxBrdf();
const Brdf& glossyBrdf();
const Brdf& phongBrdf();
const Brdf& blinnBrdf();
const Brdf& wardBrdf();
const Brdf& measuredBrdf();

namespace {

using Registry = std::array<const Brdf*, 7>;

// A plugin whose traits are incoherent (an unknown lobe axis, a width that is not a positive
// angle) is a build defect no caller could work around: the registry refuses to start, naming
// it, rather than let a sampler fall back to another plugin's policy.
const Registry& checked(const Registry& all) {
    for (const Brdf* b : all)
        if (const std::string problem = brdfTraitsProblem(*b); !problem.empty()) {
            std::fprintf(stderr, "wavelit: BRDF plugin registry: %s\n", problem.c_str());
            std::abort();
        }
    return all;
}

const Registry& registry() {
    static const Registry kAll{&lambertBrdf(), &ggxBrdf(),  &glossyBrdf(),  &phongBrdf(),
                               &blinnBrdf(),   &wardBrdf(), &measuredBrdf()};
    static const Registry& kChecked = checked(kAll);
    return kChecked;
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

std::span<const Brdf* const> brdfRegistry() { return registry(); }

int brdfIndex(const Brdf& brdf) {
    for (size_t i = 0; i < registry().size(); ++i)
        if (registry()[i] == &brdf) return int(i);
    return -1;
}

const char* defaultBrdfName() { return registry().front()->name(); }

std::string brdfParameterTooltip(std::string_view parameter) {
    std::string tip;
    for (const Brdf* b : registry())
        for (const BrdfParameterInfo& info : b->parameters())
            if (parameter == info.name)
                tip += (tip.empty() ? "" : "; ") + std::string(b->name()) + ": " + info.tooltip;
    return tip;
}

std::string brdfTraitsProblem(const Brdf& brdf) {
    const std::string who = std::string("BRDF '") + brdf.name() + "': ";
    switch (brdf.lobeAxis()) {
    case BrdfLobeAxis::Normal:
    case BrdfLobeAxis::Mirror:
        break;
    default:
        return who + "unknown lobe axis " + std::to_string(int(brdf.lobeAxis())) +
               " (neither normal nor mirror)";
    }
    // The width must be usable for every roughness the parameters allow.
    for (float r : {0.0f, 0.5f, 1.0f}) {
        BrdfParams p;
        p.roughness = r;
        const BrdfLobeWidth w = brdf.lobeWidth(p);
        if (!(std::isfinite(w.halfWidth) && w.halfWidth > 0.0 && std::isfinite(w.capHalfAngle) &&
              w.capHalfAngle > 0.0))
            return who + "lobe width not finite and positive at roughness " + std::to_string(r);
    }
    return {};
}

bool brdfReadsFile(const Brdf& brdf) {
    for (const BrdfParameterInfo& info : brdf.parameters())
        if (info.type == BrdfParameterType::File) return true;
    return false;
}

std::string brdfGpuTwinProblem(const Brdf& brdf) {
    const BrdfGpuTwin t = brdf.gpuTwin();
    auto empty = [](const char* s) { return s == nullptr || *s == '\0'; };
    if (empty(t.snippet) || empty(t.sampleFn) || empty(t.evalFn) || empty(t.pdfFn))
        return std::string("BRDF '") + brdf.name() +
               "' has no GPU twin (a GLSL snippet with sample, eval and pdf functions)";
    return {};
}

} // namespace wavelit::plugins
