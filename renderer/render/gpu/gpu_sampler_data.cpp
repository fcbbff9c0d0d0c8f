#include "render/gpu/gpu_sampler_data.h"

#include "render/sampling/oracle_sampler.h"
#include "render/sampling/product/flat_product_layout.h"
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

// One zero word when `words` has an odd count: what follows starts on an 8-byte boundary, so the
// shaders read its doubles and word pairs through samplerWords' u64 view (one load, not two:
// docs/performance.md "Lavapipe throughput (issue 12)").
void padToEven(std::vector<uint32_t>& words) {
    if (words.size() % 2 != 0)
        words.push_back(0);
}

} // namespace

GpuEnvExactLayout gpuEnvExactLayout(uint32_t offset, uint32_t width, uint32_t height) {
    GpuEnvExactLayout l;
    l.rowSolidAngle = offset + 2;
    l.rowCdf = l.rowSolidAngle + 2 * height;
    l.rowGuide = l.rowCdf + 2 * (height + 1);
    l.columnCdf = l.rowGuide + evenUp(height);
    l.columnGuide = l.columnCdf + 2 * height * (width + 1);
    l.pdfs = l.columnGuide + evenUp(height * width);
    l.end = l.pdfs + 2 * height * width;
    return l;
}

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
        d.envRoulette = misEnvRoulette(env.effectiveSolidAngle());
        d.envLevel = uint32_t(env.level());
        // The env quadtree's nodes only for the kinds that descend it (a product's leaves refine
        // into it: wavelet, oracle); the others draw from the exact tables below, and their kernel
        // reads no node (a 512 x 256 map: 5.6 MB a `mis` tracer uploaded and never read).
        if (d.lit && (kind == SamplerKind::Wavelet || kind == SamplerKind::Oracle))
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
            if (policy.mode == ProductMode::EnvMis) {
                g.mode = kGpuSamplerEnvMis;
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
            // The header at an odd word: its bins' and factors' word pairs after the 5 header
            // words, and the nodes after the (odd count of) header words, start on 8-byte
            // boundaries, so env_product_tables.glsl reads a bin in two u64 loads, a factor in
            // one, and a node (10 words, an even stride) in four: its first detail alone, then
            // (detail 2, detail 3) and its children in pairs.
            static_assert(flat_layout::kHeaderWords % 2 == 1 && flat_layout::kBinWords % 2 == 0 &&
                          flat_layout::kFactorWords % 2 == 0 && flat_layout::kNodeWords % 2 == 0 &&
                          flat_layout::kNodeDetail % 2 == 1 && flat_layout::kNodeChild % 2 == 0);
            if (d.words.size() % 2 == 0)
                d.words.push_back(0);
            g.tableOffset = uint32_t(d.words.size());
            d.words.insert(d.words.end(), flat.header.begin(), flat.header.end());
            padToEven(d.words); // a no-op: the header's word count is odd
            g.nodeOffset = uint32_t(d.words.size());
            d.words.insert(d.words.end(), flat.nodeWords.begin(), flat.nodeWords.end());
            g.scalingOffset = uint32_t(d.words.size());
            for (float s : flat.scaling)
                d.words.push_back(std::bit_cast<uint32_t>(s));
            if (!policy.aroundNormal && policy.capHalfAngle < kGpuNarrowLobeCap)
                g.mixBsdf = float(std::max(policy.mixBsdf, kGpuNarrowLobeMixBsdf));
        }
        padToEven(d.words); // the exact tables after the (even count of) tail words: 8-byte aligned
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
        pushDoubles(exact.rowSolidAngle());
        pushDoubles(exact.rowCdf());
        d.words.insert(d.words.end(), exact.rowGuide().begin(), exact.rowGuide().end());
        padToEven(d.words);
        pushDoubles(exact.columnCdf());
        d.words.insert(d.words.end(), exact.columnGuide().begin(), exact.columnGuide().end());
        padToEven(d.words);
        pushDoubles(exact.pdfTable());
    }
    if (d.words.empty())
        d.words.push_back(0);
    padToEven(d.words); // the shaders' u64 view covers every word
    return d;
}

} // namespace wavelit::render
