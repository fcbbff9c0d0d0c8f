// GLSL twin of measured.cpp and brdf_table.cpp: the MERL-layout table, multilinear between bin
// centres, cosine-weighted sampling. The tables of a scene sit in one storage buffer of floats
// (render/gpu/gpu_brdf_tables.h packs it); a material's table is found by its offset there,
// which travels in the material's roughness slot (`measured` reads no roughness), so the twin
// keeps the signatures every twin shares (plugins/brdf.h: BrdfGpuTwin). At the offset:
//   (Nθh, Nθd, Nφd, 0), then the red, green and blue blocks of Nθh Nθd Nφd floats each,
//   already scaled (BrdfTable::f).
// The generated dispatch includes this file only in kernels that bind the buffer: those compiled
// with WAVELIT_BRDF_TABLE_BINDING (render/gpu/brdf_shader_source.cpp).
#ifndef WAVELIT_MEASURED_GLSL
#define WAVELIT_MEASURED_GLSL

#include "common/constants.glsl"
#include "common/sampling.glsl"

layout(std430, binding = WAVELIT_BRDF_TABLE_BINDING) readonly buffer BrdfTables { float brdfTables[]; };

// A position between two bin centres, as brdf_table.cpp's BinCoordinate: v = (1 − t) v[i0] + t v[i1].
struct MeasuredBin {
    uint i0, i1;
    float t;
};

// An axis whose values sit at the bin centres; beyond the first and last centre the edge holds.
MeasuredBin measuredClampedBin(float fraction, uint bins) {
    float x = clamp(fraction * float(bins) - 0.5, 0.0, float(bins - 1u));
    uint i0 = min(uint(x), bins - 1u);
    return MeasuredBin(i0, min(i0 + 1u, bins - 1u), x - float(i0));
}

// φd has period π (reciprocity's fold): the last bin neighbours the first.
MeasuredBin measuredPeriodicBin(float fraction, uint bins) {
    float x = fraction * float(bins) - 0.5;
    if (x < 0.0) x += float(bins);
    uint i0 = min(uint(x), bins - 1u);
    return MeasuredBin(i0, (i0 + 1u) % bins, x - float(i0));
}

// atan(t) for t in [0, 1] to float precision (~1e-7): GLSL's atan may be off by 4096 ulp (the
// spec's bound; lavapipe's was 5e-4 relative in the table value of some pairs), and a table's
// value moves by up to a bin's jump per bin of angle. Beyond tan(π/8) the argument is reduced
// by atan(t) = π/4 + atan((t − 1)/(t + 1)); the series to z^15 then errs by < |z|^17/17 ≈ 2e-8.
float measuredAtan01(float t) {
    bool reduced = t > 0.41421356;
    float z = reduced ? (t - 1.0) / (t + 1.0) : t;
    float z2 = z * z;
    float p = z * (1.0 - z2 * (1.0 / 3.0 - z2 * (1.0 / 5.0 - z2 * (1.0 / 7.0 - z2 * (1.0 / 9.0 -
              z2 * (1.0 / 11.0 - z2 * (1.0 / 13.0 - z2 * (1.0 / 15.0))))))));
    return reduced ? 0.25 * kPi + p : p;
}

// atan2(y, x) for y >= 0, in [0, π].
float measuredAtan2(float y, float x) {
    float ax = abs(x);
    if (y == 0.0 && ax == 0.0) return 0.0;
    float a = y <= ax ? measuredAtan01(y / ax) : 0.5 * kPi - measuredAtan01(ax / y);
    return x < 0.0 ? kPi - a : a;
}

// Rusinkiewicz's half/difference angles as brdf_table.cpp's halfDiffOf: (θh, θd, φd in [0, π)).
// cos φh, sin φh, cos θh, sin θh come from h's components instead of trigonometry of its angles
// (the same numbers, fewer float roundings).
vec3 measuredHalfDiff(vec3 woIn, vec3 wiIn) {
    vec3 wo = normalize(woIn), wi = normalize(wiIn); // as brdf_table.cpp (reciprocity)
    vec3 h = normalize(wo + wi);
    float r = length(h.xy);
    float thetaH = measuredAtan2(r, h.z);
    float cp = r > 0.0 ? h.x / r : 1.0, sp = r > 0.0 ? h.y / r : 0.0;
    float ct = h.z, st = r;
    float x1 = wi.x * cp + wi.y * sp, y1 = -wi.x * sp + wi.y * cp, z1 = wi.z;
    vec3 d = vec3(x1 * ct - z1 * st, y1, x1 * st + z1 * ct);
    // φd folded into [0, π): atan2(y, x) + π for y < 0, i.e. π − atan2(|y|, x).
    float phiD = d.y >= 0.0 ? measuredAtan2(d.y, d.x) : kPi - measuredAtan2(-d.y, d.x);
    if (phiD >= kPi) phiD -= kPi;
    return vec3(thetaH, measuredAtan2(length(d.xy), d.z), phiD);
}

vec3 measuredTable(uint o, vec3 wo, vec3 wi) {
    uint nh = uint(brdfTables[o]), nd = uint(brdfTables[o + 1u]), np = uint(brdfTables[o + 2u]);
    uint n = nh * nd * np;
    uint data = o + 4u;
    vec3 a = measuredHalfDiff(wo, wi);
    MeasuredBin h = measuredClampedBin(sqrt(a.x / (0.5 * kPi)), nh);
    MeasuredBin d = measuredClampedBin(a.y / (0.5 * kPi), nd);
    MeasuredBin p = measuredPeriodicBin(a.z / kPi, np);
    vec3 sum = vec3(0.0);
    for (uint k = 0u; k < 8u; ++k) {
        float w = ((k & 1u) != 0u ? h.t : 1.0 - h.t) * ((k & 2u) != 0u ? d.t : 1.0 - d.t) *
                  ((k & 4u) != 0u ? p.t : 1.0 - p.t);
        if (w == 0.0) continue;
        uint bin = ((k & 4u) != 0u ? p.i1 : p.i0) +
                   np * (((k & 2u) != 0u ? d.i1 : d.i0) + nd * ((k & 1u) != 0u ? h.i1 : h.i0));
        sum += w * vec3(brdfTables[data + bin], brdfTables[data + n + bin], brdfTables[data + 2u * n + bin]);
    }
    return sum;
}

// `tableOffset`: the material's roughness slot (see above).
vec3 measuredEval(vec3 baseColor, float tableOffset, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
    return baseColor * measuredTable(uint(tableOffset), wo, wi);
}

float measuredPdf(float tableOffset, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0) return 0.0;
    return cosineHemispherePdf(wi);
}

bool measuredSample(vec3 baseColor, float tableOffset, vec3 wo, float u1, float u2, out vec3 wi,
                    out vec3 f, out float pdf) {
    wi = vec3(0.0, 0.0, 1.0);
    f = vec3(0.0);
    pdf = 0.0;
    if (wo.z <= 0.0) return false;
    wi = sampleCosineHemisphere(vec2(u1, u2));
    pdf = cosineHemispherePdf(wi);
    if (pdf <= 0.0) return false; // the disk's rim maps to the horizon
    f = measuredEval(baseColor, tableOffset, wo, wi);
    return true;
}

#endif
