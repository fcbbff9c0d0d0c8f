// Direction samplers of the Vulkan tracer (issue 6; render/sampling/direction_sampler.h is the CPU
// side, docs/wavelet-sampler.md the tables). Every kind returns the exact solid-angle pdf of the
// mixture it draws from, and the tracer divides by it (architecture.md §4: never the paper's eq 7).
//
//   uniform, cosine, bsdf   hemisphere / plugin sampling, as on the CPU
//   env                     the environment's equirect texels by luminance x solid angle
//                           (env_exact.glsl; the exact pdf of the radiance's pieces)
//   mis                     bsdf WAVELIT_MIS_WEIGHT + env the rest
//   wavelet                 per hit: the env factor of the reflection direction's bin times
//                           BRDF x cos, dense in private memory, refined below its leaves
//                           (product/env_product_sampler.glsl); mixed with bsdf (the policy's
//                           share) and env by the CPU's share rule and constants.
//                           Lobes the env cannot resolve (policy BsdfLobe): bsdf + env.
//                           Lobes far narrower than the env's spread (policy EnvMis): the env
//                           alone, MIS-weighted by the tracer against the BSDF, as `mis`.
//   oracle                  per hit: a dense product over a window fitted to the lobe around the
//                           exact axis (oracle_sampler.glsl), mixed as the CPU's oracle. Compiled
//                           with WAVELIT_ORACLE_SAMPLER (its private pyramid is 4x the wavelet's).
//
// The including shader includes sampling/sampler_structs.glsl and declares, before this file:
//   buffer { EnvNode envNodes[]; };  buffer { SamplerMaterial samplerMaterials[]; };
//   buffer { uint samplerWords[]; };  buffer { uint64_t samplerWords64[]; } (the same buffer, at the
//   same binding: env_exact.glsl reads its 8-byte aligned doubles through it, the product tables
//   their word pairs)
// samplerWords holds each material's flat product tables (MaterialProductTables::flatten(), its
// three arrays at the three offsets) and the env's tail cell averages (float bits).
//
// Tabulated draws keep their double square point: the pdfs of BOTH tabulated techniques are
// evaluated at that point, never at the float direction re-mapped to the square, which can land
// in the neighbouring texel (a sun's texel is 1e6 x denser than the sky beside it).
#ifndef WAVELIT_DIRECTION_SAMPLER_GLSL
#define WAVELIT_DIRECTION_SAMPLER_GLSL

#include "common/brdf.glsl"
#include "common/constants.glsl"
#include "common/octahedral.glsl"
#include "common/sampling.glsl"
#include "sampling/sampler_environment.glsl"
#include "sampling/sampler_words.glsl"
#include "sampling/env_exact.glsl"
// The product kinds' code (private pyramid, descents) only where the pipeline draws from a
// product: on lavapipe its mere presence cost the `mis` kernel ~40% of its pass (issue 12).
#ifdef WAVELIT_PRODUCT_SAMPLER
#include "sampling/product/env_product_sampler.glsl"
#include "sampling/oracle_sampler.glsl"
#endif

// Codes of render::SamplerKind (render_options.h) and of SamplerMaterial.mode (gpu_sampler_data.h).
const uint kSamplerUniform = WAVELIT_SAMPLER_UNIFORM;
const uint kSamplerCosine = WAVELIT_SAMPLER_COSINE;
const uint kSamplerBsdf = WAVELIT_SAMPLER_BSDF;
const uint kSamplerEnv = WAVELIT_SAMPLER_ENV;
const uint kSamplerMis = WAVELIT_SAMPLER_MIS;
const uint kSamplerWavelet = WAVELIT_SAMPLER_WAVELET;
const uint kSamplerOracle = WAVELIT_SAMPLER_ORACLE;
const uint kModeBsdfOnly = WAVELIT_MODE_BSDF_ONLY;
const uint kModeProduct = WAVELIT_MODE_PRODUCT;
const uint kModeBsdfLobe = WAVELIT_MODE_BSDF_LOBE;
const uint kModeOracle = WAVELIT_MODE_ORACLE;
const uint kModeEnvMis = WAVELIT_MODE_ENV_MIS;

float luminanceOf(vec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

float dsBrdfCos(DirSampler s, vec3 wiWorld) {
    vec3 l = frameToLocal(s.frame, wiWorld);
    if (l.z <= 0.0) return 0.0;
    return luminanceOf(brdfEval(s.brdfType, s.baseColor, s.roughness, s.wo, l) * l.z);
}

// --- the mixture shares (DirectionSampler::addProduct) ----------------------------------------

// Second moment of env sampling over the coarse tail cells outside the lobe's domain (the window
// when there is a product, else the cap widened by a cell).
double dsTailMoment(DirSampler s, SamplerGlobals g, bool product, vec3 axisLocal, float capAngle) {
    const int side = 1 << WAVELIT_TAIL_LEVEL;
    float cellAngle = sqrt(kFourPi) / float(side);
    float cosCap = cos(min(capAngle + cellAngle, kPi));
    double windowScale = double(1 << s.k);
    dvec2 origin = dvec2(s.ox, s.oy) * (0.5LF / windowScale);
    double sum = 0.0LF;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            vec2 p = (vec2(x, y) + 0.5) / float(side);
            if (product) {
                dvec2 local = (dvec2(p) - origin) * windowScale;
                if (local.x >= 0.0LF && local.x < 1.0LF && local.y >= 0.0LF && local.y < 1.0LF) continue;
            }
            vec3 d = octToDirection(p);
            if (!product && dot(d, axisLocal) > cosCap) continue;
            float fcos = dsBrdfCos(s, envToWorld(s.cosSinYaw, d));
            double average = uintBitsToFloat(samplerWord(g.tailOffset + uint(y * side + x)));
            sum += average * double(fcos) * double(fcos);
        }
    double dw = double(kFourPi) / double(side * side);
    return sum * double(g.envMean) * double(kFourPi) * dw;
}

// Stratified BSDF draws with the env's texel averages: the mean of (g / p)^2.
double dsBsdfLobeMoment(DirSampler s, SamplerGlobals g) {
    const int strata = WAVELIT_LOBE_STRATA;
    double sum = 0.0LF;
    for (int j = 0; j < strata; ++j)
        for (int i = 0; i < strata; ++i) {
            vec3 wi, f;
            float pdf;
            if (!brdfSample(s.brdfType, s.baseColor, s.roughness, s.wo, (float(i) + 0.5) / strata,
                            (float(j) + 0.5) / strata, wi, f, pdf) ||
                !(pdf > 0.0))
                continue;
            dvec2 p = dvec2(octToSquare(envToLocal(s.cosSinYaw, frameToWorld(s.frame, wi))));
            double texel = envPdfWithin(0, 0, 0, p) * double(g.envMean);
            double v = double(luminanceOf(f)) * double(wi.z) / double(pdf) * texel;
            sum += v * v;
        }
    return sum / double(strata * strata);
}

// --- set-up, sampling, pdf ------------------------------------------------------------------

#ifdef WAVELIT_PRODUCT_SAMPLER
// The wavelet's product for a hit: the window and env factor of the axis's bin.
float dsSetupWavelet(inout DirSampler s, SamplerMaterial sm, vec3 axisLocal, int envLevel) {
    uint factor;
    flatBinOf(sm, axisLocal, s.k, s.ox, s.oy, factor);
    s.m = min(int(flatHeader(sm, WAVELIT_FLAT_PRODUCT_LEVEL)), WAVELIT_MAX_PRODUCT_LEVEL);
    s.refineLevels = dsRefineLevels(sm, s.k + s.m, envLevel);
    return dsBuildProduct(s, sm, factor);
}
#endif

// withProduct false (a literal: the inlined copy loses the product code): the kinds without a
// product only — the `wavelet` path loop of a kernel with the per-pixel cache, whose product is
// built by pcBuild alone (sampling/product_cache.glsl).
DirSampler dsSetupWith(bool withProduct, SamplerGlobals g, SamplerMaterial sm, Frame frame, vec3 wo,
                       uint brdfType, vec3 baseColor, float roughness) {
    DirSampler s;
    s.cProduct = 0.0;
    s.cBsdf = 0.0;
    s.cEnv = 0.0;
    s.cUniform = 0.0;
    s.cCosine = 0.0;
    s.k = 0;
    s.ox = 0;
    s.oy = 0;
    s.m = 0;
    s.refineLevels = 0;
    s.massOffset = -1;
    s.frame = frame;
    s.wo = wo;
    s.brdfType = brdfType;
    s.baseColor = baseColor;
    s.roughness = roughness;
    s.cosSinYaw = g.cosSinYaw;
    s.exactOffset = g.tailOffset + uint((1 << WAVELIT_TAIL_LEVEL) * (1 << WAVELIT_TAIL_LEVEL));
    if (g.kind == kSamplerUniform) {
        s.cUniform = 1.0;
        return s;
    }
    if (g.kind == kSamplerCosine) {
        s.cCosine = 1.0;
        return s;
    }
    if (!g.lit || g.kind == kSamplerBsdf) {
        s.cBsdf = 1.0;
        return s;
    }
    if (g.kind == kSamplerEnv) {
        s.cEnv = 1.0;
        return s;
    }
    if (g.kind == kSamplerMis) {
        s.cBsdf = float(WAVELIT_MIS_WEIGHT);
        s.cEnv = float(1.0LF - WAVELIT_MIS_WEIGHT);
        return s;
    }
    // wavelet, oracle
    if (!withProduct) {
        s.cEnv = 1.0;
        return s;
    }
    if (sm.mode == kModeBsdfOnly) {
        s.cBsdf = 1.0;
        return s;
    }
    if (sm.mode == kModeEnvMis) { // policy EnvMis: `mis`'s NEE technique, the env alone
        s.cEnv = 1.0;
        return s;
    }
    vec3 nWorld = frame.n, woWorld = frameToWorld(frame, wo);
    vec3 axisWorld = sm.aroundNormal != 0u ? nWorld : 2.0 * dot(woWorld, nWorld) * nWorld - woWorld;
    vec3 axisLocal = normalize(envToLocal(g.cosSinYaw, axisWorld));
    bool product = false;
    double lobeMoment = 0.0LF;
    float total = 0.0;
#ifdef WAVELIT_PRODUCT_SAMPLER
    if (sm.mode == kModeProduct) total = dsSetupWavelet(s, sm, axisLocal, g.envLevel);
    else if (sm.mode == kModeOracle) total = dsSetupOracle(s, sm, axisLocal, g.envLevel, g.envMean);
#endif
    if (sm.mode == kModeProduct || sm.mode == kModeOracle) {
        product = total > 0.0;
        if (product) {
            // The product's integral over the window's solid angle: its second moment is close
            // to that integral squared (the product is close to the lobe's integrand).
            double windowArea = 1.0LF / double(1 << (2 * s.k));
            double lobe = double(total) / double(1 << (2 * s.m)) * double(kFourPi) * windowArea;
            lobeMoment = lobe * lobe;
        }
    }
    if (!product) lobeMoment = dsBsdfLobeMoment(s, g);
    double tail = dsTailMoment(s, g, product, axisLocal, sm.capHalfAngle);
    double a = sqrt(max(tail, 0.0LF)), bm = sqrt(max(lobeMoment, 0.0LF));
    double minEnvShare = sm.mode == kModeOracle ? WAVELIT_ORACLE_MIN_ENV_SHARE : WAVELIT_WAVELET_MIN_ENV_SHARE;
    double envShare = clamp(a / max(a + bm, 1e-300LF), minEnvShare, WAVELIT_MAX_ENV_SHARE);
    if (product) {
        s.cProduct = float(1.0LF - envShare - double(sm.mixBsdf));
        s.cBsdf = sm.mixBsdf;
        s.cEnv = float(envShare);
    } else {
        s.cBsdf = float(1.0LF - envShare);
        s.cEnv = float(envShare);
    }
    return s;
}

DirSampler dsSetup(SamplerGlobals g, SamplerMaterial sm, Frame frame, vec3 wo, uint brdfType,
                   vec3 baseColor, float roughness) {
    return dsSetupWith(true, g, sm, frame, wo, brdfType, baseColor, roughness);
}

// The mixture's solid-angle pdf at world direction wi whose octahedral point (env-local) is p.
// productDensity >= 0: the product technique's density at p per unit square area, already known
// (the draw that produced p walked the product's descent and multiplied the same shares a pdf
// walk would: re-walking it would repeat the lobe refinement's BRDF evaluations); < 0: walk it.
float dsMixturePdf(DirSampler s, vec3 wi, dvec2 p, double productDensity) {
    vec3 local = frameToLocal(s.frame, wi);
    double pdf = 0.0LF;
    if (s.cUniform > 0.0) pdf += double(s.cUniform) * (local.z > 0.0 ? double(0.5 * kInvPi) : 0.0LF);
    if (s.cCosine > 0.0) pdf += double(s.cCosine) * double(cosineHemispherePdf(local));
    if (s.cBsdf > 0.0) pdf += double(s.cBsdf) * double(brdfPdf(s.brdfType, s.roughness, s.wo, local));
    if (s.cEnv > 0.0) pdf += double(s.cEnv) * envExactPdf(s.exactOffset, wi, s.cosSinYaw);
#ifdef WAVELIT_PRODUCT_SAMPLER
    if (s.cProduct > 0.0)
        pdf += double(s.cProduct) *
               (productDensity >= 0.0LF ? productDensity : dsProductPdf(s, p)) / double(kFourPi);
#endif
    return float(pdf);
}

float dsPdf(DirSampler s, vec3 wi) {
    return dsMixturePdf(s, wi, dvec2(octToSquare(envToLocal(s.cosSinYaw, wi))), -1.0LF);
}

// u3 picks the technique (in the CPU's order: product, bsdf, env), u1 and u2 drive it.
bool dsSample(DirSampler s, float u1, float u2, float u3, out vec3 wi, out float pdf) {
    wi = vec3(0.0);
    pdf = 0.0;
    if (s.cUniform > 0.0) {
        float z = u1, r = sqrt(max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * u2;
        wi = normalize(frameToWorld(s.frame, vec3(r * cos(phi), r * sin(phi), z)));
        pdf = dsPdf(s, wi);
        return pdf > 0.0;
    }
    if (s.cCosine > 0.0) {
        wi = normalize(frameToWorld(s.frame, sampleCosineHemisphere(vec2(u1, u2))));
        pdf = dsPdf(s, wi);
        return pdf > 0.0;
    }
    bool tabulated = false, exact = false;
    dvec2 p = dvec2(0.0LF);
    double density = -1.0LF; // the product's, when it drew p
#ifdef WAVELIT_PRODUCT_SAMPLER
    if (s.cProduct > 0.0 && u3 < s.cProduct) {
        p = dsSampleProduct(s, dvec2(u1, u2), density);
        tabulated = true;
    }
#endif
    if (!tabulated && s.cEnv > 0.0 && (s.cBsdf == 0.0 || u3 >= s.cProduct + s.cBsdf)) {
        // The exact env technique: its pdf is read at the float direction, as the radiance is;
        // the product's at that direction's square point.
        vec3 local = envExactSample(s.exactOffset, dvec2(u1, u2));
        wi = normalize(envToWorld(s.cosSinYaw, local));
        p = dvec2(octToSquare(local));
        exact = true;
    }
    // One call site of dsMixturePdf (it inlines the product's pdf).
    if (exact || tabulated) {
        if (!exact) wi = envToWorld(s.cosSinYaw, octToDirection(vec2(p)));
        pdf = dsMixturePdf(s, wi, p, density);
    } else {
        vec3 local, f;
        float bsdfPdf;
        if (!brdfSample(s.brdfType, s.baseColor, s.roughness, s.wo, u1, u2, local, f, bsdfPdf))
            return false;
        wi = normalize(frameToWorld(s.frame, local));
        pdf = dsPdf(s, wi);
    }
    return pdf > 0.0 && !isinf(pdf) && !isnan(wi.x);
}

#endif
