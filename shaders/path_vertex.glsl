// The steps of path_tracer.comp's path loop (docs/estimator.md): traceSegment follows a ray to
// its hit, adding the analytic lights it crosses and, when it escapes, the environment (MIS-
// weighted against the NEE of the vertex that drew it); shadeVertex is the hit's scattering
// vertex: its emission, next-event estimation of the lights and (with direction samplers) of
// the environment, the continuation's draw and Russian roulette. Included by path_tracer.comp
// after its buffers, params, envRadiance, samplerGlobals, emissionAlongRay and nextEvent.
//
// Two code shapes, the same estimator and the same images (main() in path_tracer.comp):
// - one loop, trace then shade, each step's copy serving every vertex: a GPU runs one copy of
//   the traversal and vertex code (an H200 pass of `wavelet` is 1.4x slower with the split below);
// - WAVELIT_SPLIT_CAMERA_VERTEX (the driver defines it on CPU devices, for `wavelet`): the camera
//   vertex and its continuation's escape in their own inlined copies (productVertex /
//   productBefore true, literals), then the loop with false. `wavelet` draws from a product only
//   at its camera vertex (kWaveletProductVertices = 1), so the loop's copies are `mis`'s. On
//   lavapipe, product code anywhere in the one loop made every vertex pay for it (the sampler's
//   kind, shares and escape pdf were run-time values, the general mixture's code live at every
//   vertex, and its SIMD lanes pay for the live values): a 512^2 pass 1.44-1.64 -> 1.12-1.26
//   CPU-s (docs/performance.md "Wavelet pass cost, round 5").
#ifndef WAVELIT_PATH_VERTEX_GLSL
#define WAVELIT_PATH_VERTEX_GLSL

#if defined(WAVELIT_DIRECTION_SAMPLERS) && WAVELIT_WAVELET_PRODUCT_VERTICES != 1
#error "path_vertex.glsl: `wavelet`'s product vertex is the camera vertex alone"
#endif

const float kRayOffset = 1e-4;             // x max(1, |hit|): scale-aware self-intersection epsilon
const float kMinContinueProbability = 0.05; // Russian roulette floor
const int kRussianRouletteDepth = 2;

// A path between vertices: the ray that found the hit (tri, t, b1, b2) at `depth`, what the path
// has gathered (L) and carries (beta), its random stream.
struct PathState {
    vec3 origin;
    vec3 dir;
    uint tri;
    float t, b1, b2;
    uint depth;
    vec3 L;
    vec3 beta;
    PathSampler rng;
    uint pixelIndex;
    // The vertex that drew `dir`: its pdf of dir (0 for the camera ray) and whether it estimated
    // direct env light by NEE with `ds` (neeOfDir), with `mis`'s weights (misNeeOfDir: ds is the
    // env technique alone).
    float scatterPdf;
    bool neeOfDir;
    bool misNeeOfDir;
#ifdef WAVELIT_DIRECTION_SAMPLERS
    DirSampler ds;
#endif
#ifdef WAVELIT_PRODUCT_CACHE_BINDING
    uint cacheAt; // the pixel's cached camera-vertex mixture (sampling/product_cache.glsl)
#endif
};

// The environment the ray escaped to, MIS-weighted against the NEE of the vertex that drew it.
// productBefore false: that vertex is past `wavelet`'s product vertex, so its NEE was `mis`'s env
// technique (a literal false tells the compiler, and the product's pdf walk drops out).
void addEscapedEnvironment(bool productBefore, inout PathState st) {
    float w = 1.0;
#ifdef WAVELIT_DIRECTION_SAMPLERS
    const uint kind = WAVELIT_SAMPLER_KIND;
    if (st.neeOfDir) {
        if (st.misNeeOfDir || (kind == kSamplerWavelet && !productBefore)) {
            // `mis`'s weights: one texel lookup gives both the radiance and the technique's pdf.
            uvec2 exactSize = envExactSize(st.ds.exactOffset);
            uvec2 texel = equirectTexelOf(st.dir, st.ds.cosSinYaw, exactSize);
            w = powerHeuristic(st.scatterPdf,
                               float(envExactTexelPdfSized(st.ds.exactOffset, exactSize, texel)));
            vec3 escaped = st.beta * (w * envTexelRadiance(texel));
            st.L += escaped;
#ifdef WAVELIT_LIGHT_GROUPS
            splatGroup(environmentGroup, st.pixelIndex, escaped);
#endif
            return;
        }
        w = kind == kSamplerEnv ? 0.0 : powerHeuristic(st.scatterPdf, dsPdf(st.ds, st.dir));
    }
#endif
    vec3 escaped = st.beta * (w * envRadiance(st.dir));
    st.L += escaped;
#ifdef WAVELIT_LIGHT_GROUPS
    splatGroup(environmentGroup, st.pixelIndex, escaped);
#endif
}

// Traces st's ray (the camera ray at depth 0): the analytic lights it crosses, MIS-weighted
// against the pdf the vertex drew it with (weight 1 for the camera ray), then true with its hit in
// st.tri, t, b1, b2, or false after adding the environment it escaped to.
bool traceSegment(bool productBefore, inout PathState st) {
    uint triangleCount = params.size.w;
    uint lightCount = params.envSize.w;
    bool found = bvhTrace(st.origin, st.dir, 0.0, kFloatMax, false, triangleCount, st.tri, st.t,
                          st.b1, st.b2);
    if (lightCount > 0u)
        st.L += st.beta * emissionAlongRay(st.origin, st.dir, st.t, !found, st.scatterPdf,
                                           st.depth == 0u, lightCount, params.lightInfo.x, st.beta,
                                           st.pixelIndex);
    if (found) return true;
    addEscapedEnvironment(productBefore, st);
    return false;
}

// The vertex at st's hit; false when the path ends there, else st holds its continuation ray.
// productVertex: `wavelet`'s camera vertex, which may draw its env NEE from the pixel's product.
bool shadeVertex(bool productVertex, inout PathState st) {
    uint bounces = params.size.z;
    uint triangleCount = params.size.w;
    uint materialCount = params.envSize.z;
    uint lightCount = params.envSize.w;
    float selection = params.lightInfo.x;

    BvhTriangle T = loadTriangle(st.tri);
    vec3 position = st.origin + st.t * st.dir;
    vec3 ng = normalize(cross(T.v1.xyz - T.v0.xyz, T.v2.xyz - T.v0.xyz));
    if (dot(ng, st.dir) > 0.0) ng = -ng;
    float b0 = 1.0 - st.b1 - st.b2;
    vec3 ns = b0 * T.n0.xyz + st.b1 * T.n1.xyz + st.b2 * T.n2.xyz;
    float len = length(ns);
    ns = len > 0.0 ? ns / len : ng;
    if (dot(ns, ng) < 0.0) ns = -ns;
    if (dot(-st.dir, ns) <= 0.0) ns = ng;

    uint m = min(uint(max(T.v0.w, 0.0)), materialCount - 1u);
    Material mat = loadMaterial(m);
    st.L += st.beta * mat.emissionType.rgb;
#ifdef WAVELIT_LIGHT_GROUPS
    if (any(notEqual(mat.emissionType.rgb, vec3(0.0))))
        splatGroup(emissionGroup, st.pixelIndex, st.beta * mat.emissionType.rgb);
#endif
    if (st.depth == bounces) return false;

    Frame frame = frameFromNormal(ns);
    uint brdfType = uint(mat.emissionType.a);
    vec3 baseColor = mat.baseColorRoughness.rgb;
    float roughness = mat.baseColorRoughness.a;
    vec3 wo = frameToLocal(frame, -st.dir);
    // Lights are sampled from the continuation-ray origin, as the CPU tracer does.
    vec3 next = position + ng * (kRayOffset * max(1.0, length(position)));
#ifdef WAVELIT_DIRECTION_SAMPLERS
    // The tracer's sampler is fixed when its pipeline is made (gpu_path_tracer.cpp defines it):
    // a constant lets the compiler drop the other kinds' code (uniform/cosine continuations, the
    // general mixture set-up and pdfs); params.samplerInfo.x carries the same code.
    // docs/performance.md "`mis` pass cost, round 3": -0.65 of a 10.6 CPU-s `mis` pass.
    const uint kind = WAVELIT_SAMPLER_KIND;
    bool lit = params.samplerInfo.y != 0u;
    // The kinds whose vertex sampler draws the continuation (else it is the env NEE technique).
    bool continuationFromSampler = kind == kSamplerUniform || kind == kSamplerCosine;
    bool envNee = kind == kSamplerEnv || kind == kSamplerMis || kind == kSamplerWavelet ||
                  kind == kSamplerOracle;
    // mis's NEE: the env alone; wavelet's too past its product vertex (vertexSamplerKind).
    bool envTechniqueHere = kind == kSamplerMis || (kind == kSamplerWavelet && !productVertex);
    SamplerGlobals globals = samplerGlobals(envTechniqueHere ? kSamplerEnv : kind, lit);
    bool vertexNee = envNee && lit;
#ifdef WAVELIT_PRODUCT_CACHE_BINDING
    // wavelet: the camera vertex of a product material draws from the pixel's cached mixture
    // (its centre hit the same material), every other vertex (and a camera vertex the cache
    // does not hold) uses `mis`'s technique — bsdf alone for a material without tables, as
    // dsSetup would; the product code lives in pcBuild alone.
    if (vertexNee) {
        SamplerMaterial sm = samplerMaterials[m];
        if (!(productVertex && pcCacheableMode(sm.mode) &&
              pcLoad(st.cacheAt, m, globals, brdfType, baseColor, roughness, st.ds))) {
            globals.kind = productVertex && sm.mode == kModeBsdfOnly ? kSamplerBsdf : kSamplerEnv;
            st.ds = dsSetupWith(false, globals, sm, frame, wo, brdfType, baseColor, roughness);
        }
    }
#else
    if (continuationFromSampler || vertexNee)
        st.ds = dsSetup(globals, samplerMaterials[m], frame, wo, brdfType, baseColor, roughness);
#endif
#endif
    if (lightCount > 0u) {
        float uSelect = psNext1D(st.rng);
        vec2 ul = psNext2D(st.rng);
        vec3 direct = st.beta * nextEvent(brdfType, baseColor, roughness, frame, wo, ng, next,
                                          uSelect, ul.x, ul.y, lightCount, selection, triangleCount
#ifdef WAVELIT_DIRECTION_SAMPLERS
                                          , st.ds, continuationFromSampler
#endif
        );
        st.L += direct;
#ifdef WAVELIT_LIGHT_GROUPS
        splatGroup(groupOfLight[min(uint(uSelect * float(lightCount)), lightCount - 1u)],
                   st.pixelIndex, direct);
#endif
    }
#ifdef WAVELIT_DIRECTION_SAMPLERS
    if (envNee) {
        vec2 ue = psNext2D(st.rng);
        float ue3 = psNext1D(st.rng);
        if (vertexNee) {
            // The env technique alone (mis, wavelet's env-only vertices, env): one texel
            // lookup; `mis`'s roulette wherever the NEE is mis's (not for `env`).
            bool techniqueOnly = st.ds.cEnv == 1.0;
            bool roulette = techniqueOnly && kind != kSamplerEnv;
            vec3 envDirect =
                st.beta * envNextEvent(st.ds, techniqueOnly, roulette, st.beta, brdfType,
                                       baseColor, roughness, frame, wo, ng, next, ue.x, ue.y, ue3,
                                       kind == kSamplerEnv, triangleCount);
            st.L += envDirect;
#ifdef WAVELIT_LIGHT_GROUPS
            splatGroup(environmentGroup, st.pixelIndex, envDirect);
#endif
        }
    }
#endif

    vec2 u12 = psNext2D(st.rng);
    float u1 = u12.x, u2 = u12.y;
    vec3 wiLocal, f;
    float pdf;
    vec3 wi;
#ifdef WAVELIT_DIRECTION_SAMPLERS
    if (continuationFromSampler) {
        // The mixture's draw; the estimator divides by its pdf (architecture.md §4).
        float u3 = psNext1D(st.rng);
        vec3 wiWorld;
        if (!dsSample(st.ds, u1, u2, u3, wiWorld, pdf)) return false;
        wiLocal = frameToLocal(frame, wiWorld);
        if (wiLocal.z <= 0.0) return false;
        f = brdfEval(brdfType, baseColor, roughness, wo, wiLocal);
        wi = wiWorld;
    } else
#endif
    {
        if (!brdfSample(brdfType, baseColor, roughness, wo, u1, u2, wiLocal, f, pdf) || pdf <= 0.0)
            return false;
        wi = frameToWorld(frame, wiLocal);
    }
    if (dot(wi, ng) <= 0.0) return false; // below the true surface: light leak otherwise
    st.beta *= f * (wiLocal.z / pdf);

    if (int(st.depth) >= kRussianRouletteDepth) {
        float q = max(kMinContinueProbability, 1.0 - max(st.beta.r, max(st.beta.g, st.beta.b)));
        if (psNext1D(st.rng) < q) return false;
        st.beta /= 1.0 - q;
    }
    st.origin = next;
    st.dir = wi;
    st.depth += 1u;
    st.scatterPdf = pdf;
#ifdef WAVELIT_DIRECTION_SAMPLERS
    st.neeOfDir = vertexNee;
    st.misNeeOfDir = kind != kSamplerEnv && st.ds.cEnv == 1.0;
#endif
    return true;
}

#endif
