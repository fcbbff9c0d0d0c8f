// GuidedCdf: inverse-CDF sampling of a discrete distribution, O(1) expected per draw, monotone in
// u. Why not an alias table: the tracers' random numbers are stratified across a pixel's passes
// (util/path_sampler.h); an inverse CDF maps stratified u to stratified draws — N passes put the
// sun's share of them on a sun to within one — while an alias table scatters each entry over many
// slots, so the count of sun draws per pixel is binomial again. On the sun-lit Lambert scene that
// was 2.5x the error per sample (docs/performance.md "Env sampling by inverse CDF").
// Layout (shared with shaders/sampling/env_exact.glsl envCdfPick): n + 1 cumulative doubles
// (cdf[0] = 0, cdf[n] = 1 exactly, normalised) and n guide words: guide[k] = the first entry whose
// interval reaches past k / n, so a draw u searches only entries guide[k]..guide[k + 1] (a binary
// search over the few entries one 1/n of the mass spans).
#pragma once

#include <cstdint>
#include <vector>

namespace wavelit::render {

// Appends the cdf (n + 1 doubles) and the guide (n words) of weights w[0..n) to the two arrays.
// All-zero (or non-finite) weights: uniform.
void appendGuidedCdf(const double* w, int n, std::vector<double>& cdf, std::vector<uint32_t>& guide);

// The entry u in [0, 1) draws from the n entries at cdf / guide (as appended above): the i with
// cdf[i] <= u < cdf[i + 1] (zero-weight entries are never drawn); u is rescaled into [0, 1) within
// that entry's interval.
int pickGuidedCdf(const double* cdf, const uint32_t* guide, int n, double& u);

} // namespace wavelit::render
