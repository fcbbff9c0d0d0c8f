// The direction samplers' constants that BOTH tracers use (issue 11: one source). The C++ samplers
// read them here; the Vulkan tracer's shaders get them as #defines generated from these values at
// pipeline creation (render/gpu/sampler_shader_defines.h), so GLSL holds no copy of any of them.
// Changing one here changes both tracers (docs/wavelet-sampler.md "Constants").
#pragma once

namespace wavelit::render {

// `mis`: one-sample MIS of bsdf and env at 1/2 each (the balance heuristic in that model).
inline constexpr double kMisWeight = 0.5;
// `mis`: Russian roulette on the env NEE shadow ray. It is traced with probability
// p = min(1, max(beta f) cos w / c) (beta the path throughput, f the BRDF, w the MIS weight,
// c = misEnvRoulette(the env's effective solid angle), kMisEnvRoulette for a spread env) and its
// term divided by p. The env technique's pdf is luminance x solid angle, so
// that is the unoccluded term over the env's luminance integral: no light's or env's intensity
// enters p, and each path's estimate stays linear in every intensity (LightMix, LightRemix).
// docs/performance.md "`mis` pass cost, round 3".
inline constexpr double kMisEnvRoulette = 0.05;
// The constant c = kMisEnvRoulette applies to envs whose light is spread (effective solid angle
// (integral L)^2 / integral L^2 >= kMisEnvRouletteSolidAngle); a concentrated env (a sun) gets c
// scaled down in proportion, to at most kMisEnvRouletteMinScale x less. c compares a term with c
// times the env's integral E, and under a sun E is the sun's: shadowed and indirectly lit points,
// whose pixels are a small fraction of E, then lose most of their env terms to the coin (sun-lit
// Lambert, c = 0.05: a third more error per sample than without the roulette, 2% at c = 0.02).
// The effective solid angle is a property of the env's shape, scale-invariant, read from the
// sampler tables: p still contains no intensity, each path's estimate stays linear in each.
// docs/performance.md "The roulette scaled by the env's concentration".
inline constexpr double kMisEnvRouletteSolidAngle = 0.012;
inline constexpr double kMisEnvRouletteMinScale = 0.2;
// The roulette constant c of an env of the given effective solid angle (sr). Both tracers use
// this float: the CPU tracer in envNextEvent, the Vulkan tracer from its params block.
float misEnvRoulette(double effectiveSolidAngle);

// The env share of the product mixtures (`wavelet`, `oracle`) is chosen per shading point from
// the tail's second moment against the lobe's, c_env ~ sqrt(M_tail) / (sqrt(M_tail) +
// sqrt(M_lobe)), clamped to [min, kMaxEnvShare]: never 0 (bright tails the estimate misses keep
// support) and never all (the lobe technique keeps most samples). Every defensive share c costs
// ~c in Var/I^2 where the lobe technique is good, hence small minimums.
// `wavelet`: 0.05. Its product is truncated (K coefficients; on the GPU synthesised at 16^2), so
// bright env it misses is covered only by env sampling: at 0.02 the GPU's glossy-sphere scene had
// 18x the per-sample MSE (fireflies). The CPU used 0.02 until issue 11 (docs/wavelet-sampler.md).
inline constexpr double kWaveletMinEnvShare = 0.05;
// `oracle`: a dense product that misses nothing inside its window; 0.02 keeps it near the ideal.
inline constexpr double kOracleMinEnvShare = 0.02;
inline constexpr double kMaxEnvShare = 0.8;

// The `wavelet` mixture's defensive BSDF share (ProductPolicy::mixBsdf). The product holds the
// env, not the analytic lights, so BSDF draws are what find an area light's glossy reflection:
// ring scene at equal time, RMSE 0.498 at 0.03 vs 0.227 at 0.1 (docs/wavelet-sampler.md).
inline constexpr double kWaveletBsdfShare = 0.1;
// (The `oracle`'s, kOracleBsdfShare, is in oracle_sampler.h; both tracers read it there.)

// `wavelet` builds its per-hit product at the first kWaveletProductVertices scattering vertices of
// a path; deeper vertices estimate direct env light as `mis` does (env NEE, BSDF continuation,
// MIS). The product is most of a pass's cost (docs/performance.md "Wavelet pass cost") and pays
// most where a path's throughput is still 1: at the camera's vertex.
inline constexpr int kWaveletProductVertices = 1;

// The tracers' per-hit product (both tracers' camera vertex; the Vulkan kernel's at every product
// vertex): the bin's env factor synthesised to at most 2^kTracerMaxProductLevel x
// 2^kTracerMaxProductLevel leaves (not the policy's 2^5: the kernel keeps the pyramid in private
// memory and pays (2^m + 1)^2 BRDF evaluations per build), each leaf's average (clamped at 0)
// times BRDF x cos env-weighted over its 2 x 2 sub-cells (f cos at the sub-cell centres
// interpolated from the leaf's corners), untruncated; the lobe refinement and the env's quadtree
// refine below the leaves. DirectionSampler's ProductBuild::Tracer is the C++ build of
// it, the paper's sparse product (ProductBuild::Paper) the samplers' reference.
inline constexpr int kTracerMaxProductLevel = 4;
// The defensive BSDF share of a narrow mirror lobe's tracer product (kWaveletBsdfShare, 0.1,
// elsewhere): a lobe whose cap is under kTracerNarrowLobeCap (the policy's 64 x 64-bin class)
// has a window whose 16^2 leaves are wider than the paper product's 32^2 resolve, and the lobe's
// own sampling follows it exactly. Exact GPU variance at the sun study: ggx r = 0.1
// 0.466 -> 0.326 (mis 0.438), blinn r = 0.2 0.523 -> 0.418 (mis 0.46); 0.25 for every mirror
// lobe cost the wider ones up to 1.4x (ggx r = 0.5 0.76 -> 1.06): docs/brdfs.md, last section.
inline constexpr double kTracerNarrowLobeCap = 0.3; // radians
inline constexpr double kTracerNarrowLobeMixBsdf = 0.25;

// "Model only what a scene needs" for the product (issue 12, docs/performance.md "Wavelet pass
// cost, round 3" and "Comparable extents, two-sided"). The product pays where env and lobe are of
// comparable extent; it cannot where one is far wider than the other, and the material's vertices
// then estimate direct env light as `mis` does (ProductMode::EnvMis; both tracers read the
// policy). Extents: the env's effective solid angle (integral L)^2 / integral L^2 and a mirror
// lobe's 2 pi (1 - cos half-width). Hemisphere-wide lobes about the normal are not judged by
// extents: they are EnvMis under every env ("Equal time, round 5").
// The product's pass costs ~1.6-2.3x mis's, so it pays at equal time only where it cuts the error
// per sample by more than that; measured (docs/performance.md "Comparable extents, two-sided",
// relRMSE^2 x spp against mis) it does so only where the env is somewhat wider than the lobe.
// Env wider than kEnvMisSolidAngleRatio x the lobe: BSDF sampling follows the env across the
// lobe. The default scene's gold (studio, env 3.9x the lobe) wins ~1.6x per sample and keeps its
// product; at 5.9x / 9.5x (the gold at r = 0.18 / 0.16) ~1.35x, cornell_box's ggx box (7.6x) ties:
// 6 keeps the gold and hands over the rest, which cannot pay for the pass.
inline constexpr double kEnvMisSolidAngleRatio = 6.0;
// A constant env (4 pi sr) keeps the previous threshold: its product is the lobe itself, and the
// furnace's ggx r = 0.6 (env 8x the lobe) reached 1% in 44 passes on it where mis's technique
// needs ~1100 (tests/sampler_furnace_test.cpp).
inline constexpr double kUniformEnvMisSolidAngleRatio = 16.0;
// Lobe wider than kLobeMisSolidAngleRatio x the env: the light sits inside the lobe, which is near
// constant across it, so mis's exact env technique follows the integrand already. Under the city
// HDRI's sun (env 0.0048 sr) the product is worse per sample than mis at lobe / env 1.3 (r =
// 0.15: 1.6-2.4x), 2.7, 4.2 (r = 0.2: 5%), 21 and 66 (r = 0.3 / 0.4: 5-32%); under the studio it
// still wins 1.5x at 0.85 (r = 0.27) and 1.25x at 6.5 (r = 0.45: not enough for the pass).
inline constexpr double kLobeMisSolidAngleRatio = 1.0;

// The share rule's moment estimates: the lobe's without a product from kLobeStrata^2 stratified
// BSDF draws; the tail's on the env's 2^kTailLevel square cells (64 BRDF evaluations; 16^2 changed
// no share in the variance study and costs 4x).
inline constexpr int kLobeStrata = 4;
inline constexpr int kTailLevel = 3;

// Lobe refinement below a product's leaves (env_product_sampler.h): each child keeps at least this
// fraction of the largest child's BRDF weight, so a child whose centre sees f cos = 0 (the
// horizon crossing it) keeps product support.
inline constexpr double kLobeFloor = 0.02;

// The oracle's window may shrink until its product texels are 2^-this env texels.
inline constexpr int kOracleDepthBelowEnv = 6;

// chooseWindow (sampler_window.h): the cap's rim is probed at kRimProbes azimuths (and on a ring
// at kRimInnerRing of the angle); the octahedral map is smooth away from its folds, so a
// 7.5-degree spacing misses at most a sliver the defensive techniques cover anyway. An image
// wider than kMaxCompactExtent of the square has crossed a fold (or is a hemisphere): the whole
// square.
inline constexpr int kRimProbes = 48;
inline constexpr double kRimInnerRing = 0.5;
inline constexpr double kMaxCompactExtent = 0.5;

} // namespace wavelit::render
