// The `oracle`'s per-hit product (render/sampling/oracle_sampler.h is the CPU side): a DENSE
// 2^WAVELIT_ORACLE_LEVEL square product of env cell averages x BRDF x cos (env-weighted at 2 x 2
// sub-cells per leaf) over a window fitted to the lobe around the exact axis (dsChooseWindow),
// refined like the wavelet's product (dsDescendProduct). The CPU's 128^2 grid would take 21 KiB of
// private memory and ~65k BRDF evaluations per hit; this one ~4k (docs/wavelet-sampler.md).
#ifndef WAVELIT_ORACLE_SAMPLER_GLSL
#define WAVELIT_ORACLE_SAMPLER_GLSL

#include "sampling/product/env_product_sampler.glsl"
#include "sampling/sampler_window.glsl"

// The oracle's leaves: the leaf's exact env average times its env-weighted BRDF x cos, i.e. the
// mean over its 2 x 2 sub-cells of (env average there) x BRDF x cos at the sub-cell's centre: the
// masses of the dense product one level finer (the CPU's windowTabulateEnvWeighted x
// windowEnvGrid). Returns the total (0: nothing to sample).
float dsBuildOracleProduct(DirSampler s, float envMean) {
    int m = s.m, side = 1 << m, off = pyramidOffset(m);
    int level = s.k + m;
    double toAverage = powerOfFour(level) * double(envMean);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            int gx = (s.ox << (m - 1)) + x, gy = (s.oy << (m - 1)) + y;
            double sub[4];
            envSubCellMasses(level, gx, gy, sub);
            double mass = sub[0] + sub[1] + sub[2] + sub[3];
            gMass[off + y * side + x] =
                mass > 0.0LF ? float(mass * toAverage) * dsEnvWeightedBrdfCos(s, level, gx, gy, sub) : 0.0;
        }
    return dsSumPyramid(m);
}

// The oracle's window and product for a hit around env-local `axisLocal`: leaves down to
// 2^-WAVELIT_ORACLE_DEPTH_BELOW_ENV env texels (OracleOptions::depthBelowEnv).
float dsSetupOracle(inout DirSampler s, SamplerMaterial sm, vec3 axisLocal, int envLevel,
                    float envMean) {
    int maxK = max(1, envLevel + WAVELIT_ORACLE_DEPTH_BELOW_ENV - WAVELIT_ORACLE_LEVEL);
    dsChooseWindow(axisLocal, sm.capHalfAngle, maxK, s.k, s.ox, s.oy);
    s.m = WAVELIT_ORACLE_LEVEL;
    s.refineLevels = dsRefineLevels(sm, s.k + s.m, envLevel);
    return dsBuildOracleProduct(s, envMean);
}

#endif
