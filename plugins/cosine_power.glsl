// GLSL twin of cosine_power.h: cosine powers through x = 1 − cosθ (exponents up to 1e7 at
// r = 0.02), the Phong exponent of a roughness, and the sampling of cos^(m−1)θ.
#ifndef WAVELIT_COSINE_POWER_GLSL
#define WAVELIT_COSINE_POWER_GLSL

const float kCosPowMinAlpha = 1e-4;

float cosPowAlpha(float roughness) { return max(roughness * roughness, kCosPowMinAlpha); }

float cosPowExponent(float roughness) {
    float a = cosPowAlpha(roughness);
    return 2.0 / (a * a) - 2.0;
}

float cosPowLogOneMinus(float x) {
    if (x < 1e-2) return -x * (1.0 + x * (0.5 + x * (1.0 / 3.0 + x * 0.25)));
    return log(1.0 - x);
}

float cosPowOneMinus(float x, float n) {
    if (x >= 1.0) return n == 0.0 && x == 1.0 ? 1.0 : 0.0;
    return exp(n * cosPowLogOneMinus(x));
}

float cosPowSampleOneMinusCos(float u, float m) {
    float t = -log(1.0 - u) / m;
    return t < 1e-3 ? t * (1.0 - t * (0.5 - t * (1.0 / 6.0))) : 1.0 - exp(-t);
}

#endif
