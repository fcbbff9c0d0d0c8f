// Next-event estimation of direct environment light (CpuPathTracer::envNextEvent is the CPU
// twin; docs/estimator.md "Direction samplers"), included by path_tracer.comp after its buffers,
// params and envRadiance. Two things keep a `mis` pass cheap on lavapipe (docs/performance.md
// "`mis` pass cost, round 3"):
// - an env-only technique (mis, env, wavelet past its product vertices) draws its texel and reads
//   the pdf and the radiance at the ONE texel of the drawn float direction: the same numbers as
//   dsSample + envRadiance, one equirect lookup (two atans) instead of two;
// - `mis` plays Russian roulette with the shadow ray (params.samplerEnv.y), and so do `wavelet`'s
//   env-only vertices (past its product vertices, EnvMis materials): their NEE is `mis`'s.
#ifndef WAVELIT_ENV_NEE_GLSL
#define WAVELIT_ENV_NEE_GLSL

// The radiance of texel t of the map (a constant env: its scale), as environmentRadiance reads.
vec3 envTexelRadiance(uvec2 t) {
    uvec2 size = params.envSize.xy;
    if (size.x == 0u || size.y == 0u) return params.envScale.rgb;
    uint i = 3u * (t.y * size.x + t.x);
    return envTexelAt(i) * params.envScale.rgb;
}

// Direct env light from the vertex's NEE technique `ds`, shadow ray, MIS against the BSDF
// continuation (unweighted: the `env` sampler, weight 1). envTechniqueOnly: ds is the env
// technique alone (DirectionSampler::envTechniqueOnly on the CPU).
// roulette (`mis`): the shadow ray is traced with probability p = min(1, max(beta f) cos w / c),
// c = params.samplerEnv.y, and its term divided by p (c: sampler_constants.h misEnvRoulette, from
// the env's effective solid angle, a property of its shape). With the env technique's pdf
// proportional to luminance x solid angle, Le / pdf has the luminance of the env's integral, so
// max(beta f) cos w is the unoccluded term over that integral (up to the texel's chroma): p
// depends on no light's, tint's or env's intensity, and every path's estimate stays linear in
// each of them (LightMix). u3 is the coin: an env-only technique draws no technique with it.
vec3 envNextEvent(DirSampler ds, bool envTechniqueOnly, bool roulette, vec3 beta, uint type,
                  vec3 baseColor, float roughness, Frame frame, vec3 wo, vec3 ng, vec3 o, float u1,
                  float u2, float u3, bool unweighted, uint triangleCount) {
    vec3 wiWorld;
    float pdf;
    uvec2 texel = uvec2(0u);
    if (envTechniqueOnly) {
        // dsSample's exact-env branch with cEnv = 1, the pdf read once at the radiance's texel.
        // The tables' size read once for the draw, the texel and its pdf.
        uvec2 size = envExactSize(ds.exactOffset);
        vec3 local = envExactSampleSized(ds.exactOffset, size, dvec2(u1, u2));
        wiWorld = normalize(envToWorld(ds.cosSinYaw, local));
        texel = equirectTexelOf(wiWorld, ds.cosSinYaw, size);
        pdf = float(envExactTexelPdfSized(ds.exactOffset, size, texel));
        if (!(pdf > 0.0) || isinf(pdf) || isnan(wiWorld.x)) return vec3(0.0);
    } else if (!dsSample(ds, u1, u2, u3, wiWorld, pdf)) {
        return vec3(0.0);
    }
    if (dot(wiWorld, ng) <= 0.0) return vec3(0.0);
    vec3 wi = frameToLocal(frame, wiWorld);
    if (wi.z <= 0.0) return vec3(0.0);
    vec3 f = brdfEval(type, baseColor, roughness, wo, wi);
    if (all(equal(f, vec3(0.0)))) return vec3(0.0);
    float w = unweighted ? 1.0 : powerHeuristic(pdf, brdfPdf(type, roughness, wo, wi));
    float scale = wi.z * w / pdf;
    if (roulette) {
        vec3 bf = beta * f;
        float p = max(bf.r, max(bf.g, bf.b)) * wi.z * w / params.samplerEnv.y;
        if (p < 1.0) {
            if (!(u3 < p)) return vec3(0.0);
            scale /= p;
        }
    }
    uint tri;
    float t, b1, b2;
    if (bvhTrace(o, wiWorld, 0.0, kFloatMax, true, triangleCount, tri, t, b1, b2))
        return vec3(0.0);
    vec3 Le = envTechniqueOnly ? envTexelRadiance(texel) : envRadiance(wiWorld);
    return f * Le * scale;
}

#endif
