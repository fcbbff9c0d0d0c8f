#include "render/gpu/gpu_sampler_data.h"

#include "render/gpu/precomputed_products.h"

#include "render/sampling/oracle_sampler.h"
#include "render/sampling/sampler_constants.h"

#include <algorithm>
#include <bit>
#include <string>

namespace wavelit::render {

size_t GpuSamplerData::bytes() const {
    return envNodes.size() * sizeof(envNodes[0]) + materials.size() * sizeof(GpuSamplerMaterial) +
           words.size() * sizeof(uint32_t);
}

namespace {

// The oracle needs no tables: its material entry says how to fit and mix the per-hit product.
GpuSamplerMaterial oracleMaterial(const SamplerMaterial& m) {
    GpuSamplerMaterial g;
    g.mode = kGpuSamplerOracle;
    g.mixBsdf = float(kOracleBsdfShare);
    g.capHalfAngle = float(oracleCapHalfAngle(*m.brdf, m.params));
    g.aroundNormal = m.brdf->lobeAxis() == plugins::BrdfLobeAxis::Normal ? 1u : 0u;
    g.refineMaxLevels = kGpuOracleRefineLevels;
    g.refineCellAngle = 1e-30f; // refine by level count only
    return g;
}

} // namespace

util::Result<GpuSamplerData> packGpuSamplers(const SceneSamplerTables& tables, SamplerKind kind,
                                             size_t gpuMaterialCount) {
    GpuSamplerData d;
    d.kind = uint32_t(kind);
    d.materials.assign(gpuMaterialCount, GpuSamplerMaterial{});
    d.envNodes.push_back({});
    if (tables.tables) {
        const DirectionSamplerTables& t = *tables.tables;
        const SamplerEnvironment& env = t.environment();
        d.lit = env.hasLight();
        d.envMean = float(env.cellAverage(0, 0, 0));
        d.envIntegral = float(env.exact().integral());
        d.envLevel = uint32_t(env.level());
        if (d.lit)
            d.envNodes = env.fine().table();
        for (size_t i = 0; i < gpuMaterialCount && i < tables.samplerIndexOfMaterial.size(); ++i) {
            const int index = tables.samplerIndexOfMaterial[i];
            if (index < 0)
                continue;
            if (kind == SamplerKind::Oracle) {
                d.materials[i] = oracleMaterial(t.material(size_t(index)));
                continue;
            }
            const MaterialProductTables* product = t.productTables(size_t(index));
            if (!product)
                continue; // kinds other than wavelet: the material needs nothing
            const ProductPolicy& policy = product->policy();
            GpuSamplerMaterial& g = d.materials[i];
            g.mixBsdf = float(policy.mixBsdf); // the CPU's (sampler_constants.h)
            g.capHalfAngle = float(policy.capHalfAngle);
            g.aroundNormal = policy.aroundNormal ? 1u : 0u;
            g.refineMaxLevels = uint32_t(std::max(0, policy.refineMaxLevels));
            g.refineCellAngle = float(policy.refineCellAngle);
            if (policy.mode == ProductMode::BsdfLobe) {
                g.mode = kGpuSamplerBsdfLobe;
                continue;
            }
            if (policy.productLevel < 1)
                return util::makeError(util::ErrorKind::Unsupported, "",
                                       "material '" + t.material(size_t(index)).name +
                                           "': product level " +
                                           std::to_string(policy.productLevel) +
                                           " (the GPU needs at least 1)");
            const FlatProductTables flat = product->flatten();
            g.mode = kGpuSamplerProduct;
            g.tableOffset = uint32_t(d.words.size());
            d.words.insert(d.words.end(), flat.header.begin(), flat.header.end());
            g.nodeOffset = uint32_t(d.words.size());
            d.words.insert(d.words.end(), flat.nodeWords.begin(), flat.nodeWords.end());
            g.scalingOffset = uint32_t(d.words.size());
            for (float s : flat.scaling)
                d.words.push_back(std::bit_cast<uint32_t>(s));
            // No precomputed pyramids for glossy lobes with a Gaussian tail (blinn, ward, phong):
            // their hits build their own product. Read from the tables (a canonical lobe per
            // axis bin), the exact GPU variance at the sun study's point was 4-60x worse than
            // the per-hit product's and 2-12x worse than `mis` (blinn r = 0.1: 4.27 -> 0.354,
            // ward aniso r = 0.2: 47.9 -> 1.23, phong r = 0.1: 6.13 -> 0.258; docs/brdfs.md).
            const SamplerMaterial& sm = t.material(size_t(index));
            const bool gaussianGlossy = !policy.aroundNormal && sm.brdf &&
                                        sm.brdf->lobeWidth(sm.params).tail == plugins::BrdfTail::Gaussian;
            if (d.lit && !gaussianGlossy) {
                const int m = std::min(policy.productLevel, kGpuMaxProductLevel);
                const std::vector<uint32_t> bins =
                    buildPrecomputedProducts(env, t.material(size_t(index)), m, *product);
                g.precomputedOffset = uint32_t(d.words.size());
                g.precomputedBins = 1u << axisBinLevel(*product);
                d.words.insert(d.words.end(), bins.begin(), bins.end());
            }
        }
        d.tailOffset = uint32_t(d.words.size());
        const int side = 1 << kTailLevel;
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                d.words.push_back(
                    std::bit_cast<uint32_t>(float(env.cellAverage(kTailLevel, x, y))));
        // The exact env technique's tables right after (sampling/env_exact.glsl).
        const EquirectEnvSampler& exact = env.exact();
        d.words.push_back(uint32_t(exact.width()));
        d.words.push_back(uint32_t(exact.height()));
        auto pushDoubles = [&](const std::vector<double>& v) {
            for (double x : v) {
                const uint64_t bits = std::bit_cast<uint64_t>(x);
                d.words.push_back(uint32_t(bits));
                d.words.push_back(uint32_t(bits >> 32));
            }
        };
        auto pushSlots = [&](const std::vector<EquirectEnvSampler::AliasSlot>& v) {
            for (const EquirectEnvSampler::AliasSlot& s : v) {
                d.words.push_back(std::bit_cast<uint32_t>(s.threshold));
                d.words.push_back(s.alias);
            }
        };
        pushDoubles(exact.rowSolidAngle());
        pushSlots(exact.rowAlias());
        pushSlots(exact.columnAlias());
        pushDoubles(exact.pdfTable());
    }
    if (d.words.empty())
        d.words.push_back(0);
    return d;
}

} // namespace wavelit::render
