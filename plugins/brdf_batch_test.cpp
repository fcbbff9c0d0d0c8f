// Brdf::evalBatch equals eval (plugins/brdf.h): for every registered plugin (the vectorised
// overrides of ggx, glossy and lambert, and the default loop of the others), many (wo, wi) pairs
// over the sphere — below the horizon, grazing, near the mirror direction — and roughness from
// mirror-like to 1. The contract is float rounding (1e-6 relative); the overrides compute the
// same operations in the same order, so in practice they agree bit for bit (docs/relighting.md §7.0f).
#include "plugins/brdf.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace wavelit::plugins {
namespace {

glm::vec3 uniformSphere(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float z = 1.0f - 2.0f * u(rng), phi = 6.28318530718f * u(rng);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

TEST(BrdfBatch, EvalBatchEqualsEvalForEveryPluginToFloatRounding) {
    std::mt19937 rng(7);
    for (const Brdf* brdf : brdfRegistry()) {
        if (brdfReadsFile(*brdf)) continue; // `measured` needs its table (it keeps the default loop)
        for (float roughness : {0.02f, 0.1f, 0.3f, 0.55f, 1.0f})
            for (const glm::vec3& colour : {glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(0.9f, 0.6f, 0.2f)}) {
                const BrdfParams params(colour, roughness, 0.3f);
                for (int view = 0; view < 24; ++view) {
                    // Random views, a few below the horizon, one straight on, one at grazing.
                    glm::vec3 wo = view == 0 ? glm::vec3(0, 0, 1)
                                   : view == 1 ? glm::normalize(glm::vec3(1.0f, 0.0f, 0.02f))
                                               : uniformSphere(rng);
                    if (view > 1 && view % 5 != 0) wo.z = std::abs(wo.z);
                    std::vector<float> x, y, z;
                    for (int i = 0; i < 512; ++i) {
                        glm::vec3 wi = uniformSphere(rng);
                        if (i % 7 == 0) wi = glm::normalize(glm::vec3(-wo.x, -wo.y, wo.z) + 0.05f * wi); // near the mirror
                        if (i % 61 == 0) wi.z = 0.0f; // exactly on the horizon
                        x.push_back(wi.x);
                        y.push_back(wi.y);
                        z.push_back(wi.z);
                    }
                    std::vector<float> r(x.size()), g(x.size()), b(x.size());
                    brdf->evalBatch(params, wo, {x.data(), y.data(), z.data(), x.size()}, {r.data(), g.data(), b.data()});
                    for (size_t i = 0; i < x.size(); ++i) {
                        const glm::vec3 want = brdf->eval(params, wo, glm::vec3(x[i], y[i], z[i]));
                        const glm::vec3 got(r[i], g[i], b[i]);
                        for (int c = 0; c < 3; ++c)
                            ASSERT_LE(std::abs(got[c] - want[c]), 1e-6f * std::max(std::abs(got[c]), std::abs(want[c])))
                                << brdf->name() << " r=" << roughness << " channel " << c << " view " << view << " i=" << i
                                << ": batch " << got[c] << " vs eval " << want[c];
                    }
                }
            }
    }
}

} // namespace
} // namespace wavelit::plugins
