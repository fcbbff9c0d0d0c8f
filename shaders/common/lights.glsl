// One analytic light (point, sphere, rect, spot, sun): GLSL twin of renderer/render/
// light_sampler.cpp and light_spherical_rect.cpp, docs/estimator.md "Analytic lights". Same
// formulas in the same order, all float; the constants derived once per light (emission, axes,
// cone terms) are computed on the CPU in double exactly as LightSampler's constructor does
// (render/gpu/gpu_scene_data.cpp packs them) and read from `Light`.
#ifndef WAVELIT_LIGHTS_GLSL
#define WAVELIT_LIGHTS_GLSL

#include "common/constants.glsl"
#include "common/sampling.glsl"

// Type codes shared with render/gpu/gpu_scene_data.h (kGpuLight*).
const uint kLightPoint = 0u;
const uint kLightSphere = 1u; // r > 0 only: a zero radius is packed as a point
const uint kLightRect = 2u;
const uint kLightSpot = 3u;
const uint kLightSun = 4u;

// Mirrors GpuLight (std430, 96 bytes).
struct Light {
    vec4 positionType; // xyz position, w = type code
    vec4 normalRadius; // xyz normalised `direction` (the way light travels), w = sphere radius
    vec4 emissionArea; // rgb: area L, point/spot I = Phi/(4 pi), delta sun E; w = rect area
    vec4 axisUInner;   // xyz rect half-extent axis U, w = spot cos(inner)
    vec4 axisVOuter;   // xyz rect half-extent axis V, w = spot cos(outer)
    vec4 sun;          // x = sin^2(theta_s), y = 1 - cos(theta_s), z = 1 for delta lights
};

const float kLightMinDistance2 = 1e-12;
const float kLightRimSlack2 = (1.0 + 1e-4) * (1.0 + 1e-4);
const float kLightEdgeSlack = 1.0 + 1e-5;
const float kMinSphericalRectSolidAngle = 1e-2; // light_spherical_rect.h
const float kSphericalRectEdgeGuard = 1e-6;

struct LightSample {
    vec3 wi;
    float distance; // kFloatMax for the sun (the CPU's infinity, clamped as its shadow ray is)
    vec3 value;
    float pdf;
    bool delta;
    bool valid;
};

uint lightType(Light l) { return uint(l.positionType.w); }
bool lightIsDelta(Light l) { return l.sun.z != 0.0; }

// Power heuristic a^2 / (a^2 + b^2) as 1 / (1 + (b/a)^2) (render/lights/light_set.cpp).
float powerHeuristic(float a, float b) {
    if (!(a > 0.0)) return 0.0;
    float r = b / a;
    return 1.0 / (1.0 + r * r);
}

vec3 lightSampleCone(vec3 axis, float oneMinusCos, float u1, float u2, out float sin2) {
    float x = u1 * oneMinusCos;
    sin2 = max(0.0, x * (2.0 - x));
    float sinTheta = sqrt(sin2);
    float phi = 2.0 * kPi * u2;
    Frame frame = frameFromNormal(axis);
    return normalize(frameToWorld(frame, vec3(sinTheta * cos(phi), sinTheta * sin(phi), 1.0 - x)));
}

float lightConePdf(float oneMinusCos) { return 1.0 / (2.0 * kPi * oneMinusCos); }

float sphereOneMinusCos(float r2, float d2) {
    float sin2 = r2 / d2;
    return sin2 / (1.0 + sqrt(max(0.0, 1.0 - sin2)));
}

// --- Spherical rectangle (Urena, Fajardo, King 2013), twin of light_spherical_rect.cpp.
struct SphericalRect {
    vec3 o, x, y, z;
    float z0, x0, y0, x1, y1;
    float b0, b1, k, solidAngle;
};

// acos(clamp(-dot(a, b), -1, 1)) as the CPU computes it, but through atan(y, x): Mesa lowers
// GLSL acos to a short polynomial with ~1e-4 rad error, which S = g0 + g1 + g2 + g3 - 2 pi
// then amplifies; its atan is accurate to ~1e-6. (1 - c)(1 + c) keeps sin exact near c = +-1.
float sphericalRectAngle(vec3 a, vec3 b) {
    float c = clamp(-dot(a, b), -1.0, 1.0);
    return atan(sqrt(max(0.0, (1.0 - c) * (1.0 + c))), c);
}

SphericalRect sphericalRectMake(vec3 corner, vec3 ex, vec3 ey, vec3 o) {
    SphericalRect r;
    r.o = o;
    float exl = length(ex), eyl = length(ey);
    r.x = ex / exl;
    r.y = ey / eyl;
    r.z = cross(r.x, r.y);
    vec3 d = corner - o;
    r.z0 = dot(d, r.z);
    if (r.z0 > 0.0) {
        r.z = -r.z;
        r.z0 = -r.z0;
    }
    r.x0 = dot(d, r.x);
    r.y0 = dot(d, r.y);
    r.x1 = r.x0 + exl;
    r.y1 = r.y0 + eyl;
    vec3 v00 = vec3(r.x0, r.y0, r.z0), v01 = vec3(r.x0, r.y1, r.z0), v10 = vec3(r.x1, r.y0, r.z0),
         v11 = vec3(r.x1, r.y1, r.z0);
    vec3 n0 = normalize(cross(v00, v10));
    vec3 n1 = normalize(cross(v10, v11));
    vec3 n2 = normalize(cross(v11, v01));
    vec3 n3 = normalize(cross(v01, v00));
    float g0 = sphericalRectAngle(n0, n1), g1 = sphericalRectAngle(n1, n2),
          g2 = sphericalRectAngle(n2, n3), g3 = sphericalRectAngle(n3, n0);
    r.b0 = n0.z;
    r.b1 = n2.z;
    r.k = 2.0 * kPi - g2 - g3;
    r.solidAngle = g0 + g1 - r.k;
    return r;
}

vec3 sphericalRectSample(SphericalRect r, float u1, float u2) {
    float au = u1 * r.solidAngle + r.k;
    float fu = (cos(au) * r.b0 - r.b1) / sin(au);
    float cu = (fu >= 0.0 ? 1.0 : -1.0) / sqrt(fu * fu + r.b0 * r.b0);
    cu = clamp(cu, -1.0, 1.0);
    float xu = clamp(-(cu * r.z0) / sqrt(max(0.0, 1.0 - cu * cu)), r.x0, r.x1);
    float d = sqrt(xu * xu + r.z0 * r.z0);
    float h0 = r.y0 / sqrt(d * d + r.y0 * r.y0);
    float h1 = r.y1 / sqrt(d * d + r.y1 * r.y1);
    float hv = h0 + u2 * (h1 - h0), hv2 = hv * hv;
    float yv = hv2 < 1.0 - kSphericalRectEdgeGuard ? hv * d / sqrt(1.0 - hv2) : r.y1;
    return r.o + xu * r.x + yv * r.y + r.z0 * r.z;
}

SphericalRect lightSphericalRect(Light l, vec3 p) {
    vec3 u = l.axisUInner.xyz, v = l.axisVOuter.xyz;
    return sphericalRectMake(l.positionType.xyz - u - v, 2.0 * u, 2.0 * v, p);
}

float lightSpotFalloff(Light l, vec3 fromLight) {
    float cosAlpha = dot(fromLight, l.normalRadius.xyz);
    float cosInner = l.axisUInner.w, cosOuter = l.axisVOuter.w;
    if (!(cosInner > cosOuter)) return cosAlpha >= cosOuter ? 1.0 : 0.0;
    float t = clamp((cosAlpha - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

LightSample lightSampleInvalid() {
    LightSample s;
    s.wi = vec3(0.0);
    s.distance = 0.0;
    s.value = vec3(0.0);
    s.pdf = 0.0;
    s.delta = false;
    s.valid = false;
    return s;
}

// Direction toward the light from p (LightSampler::sample).
LightSample lightSample(Light l, vec3 p, float u1, float u2) {
    LightSample s = lightSampleInvalid();
    uint type = lightType(l);
    vec3 pos = l.positionType.xyz;
    vec3 n = l.normalRadius.xyz;
    if (type == kLightSphere) {
        vec3 toCentre = pos - p;
        float r = l.normalRadius.w;
        float d2 = dot(toCentre, toCentre), r2 = r * r;
        if (!(d2 > r2)) return s;
        float oneMinusCos = sphereOneMinusCos(r2, d2);
        if (!(oneMinusCos > 0.0)) return s;
        float d = sqrt(d2);
        float sin2;
        s.wi = lightSampleCone(toCentre / d, oneMinusCos, u1, u2, sin2);
        float cosTheta = 1.0 - u1 * oneMinusCos;
        s.distance = max(0.0, d * cosTheta - sqrt(max(0.0, r2 - d2 * sin2)));
        s.value = l.emissionArea.rgb;
        s.pdf = lightConePdf(oneMinusCos);
        s.valid = true;
        return s;
    }
    if (type == kLightRect) {
        float area = l.emissionArea.w;
        if (!(area > 0.0) || !(dot(p - pos, n) > 0.0)) return s;
        SphericalRect sr = lightSphericalRect(l, p);
        bool spherical = sr.solidAngle >= kMinSphericalRectSolidAngle;
        vec3 q = spherical ? sphericalRectSample(sr, u1, u2)
                           : pos + (2.0 * u1 - 1.0) * l.axisUInner.xyz +
                                 (2.0 * u2 - 1.0) * l.axisVOuter.xyz;
        vec3 toPoint = q - p;
        float d2 = dot(toPoint, toPoint);
        if (!(d2 > 0.0)) return s;
        float d = sqrt(d2);
        vec3 wi = toPoint / d;
        float cosLight = -dot(wi, n);
        if (!(cosLight > 0.0)) return s;
        s.wi = wi;
        s.distance = d;
        s.value = l.emissionArea.rgb;
        s.pdf = spherical ? 1.0 / sr.solidAngle : d2 / (area * cosLight);
        s.valid = !isinf(s.pdf) && !isnan(s.pdf);
        return s;
    }
    if (type == kLightSun) {
        s.distance = kFloatMax;
        s.value = l.emissionArea.rgb;
        s.valid = true;
        if (lightIsDelta(l)) {
            s.wi = -n;
            s.pdf = 1.0;
            s.delta = true;
            return s;
        }
        float sin2;
        s.wi = lightSampleCone(-n, l.sun.y, u1, u2, sin2);
        s.pdf = lightConePdf(l.sun.y);
        return s;
    }
    // Point and spot.
    vec3 toLight = pos - p;
    float d2 = dot(toLight, toLight);
    if (!(d2 > kLightMinDistance2)) return s;
    s.distance = sqrt(d2);
    s.wi = toLight / s.distance;
    s.value = l.emissionArea.rgb / d2;
    if (type == kLightSpot) s.value *= lightSpotFalloff(l, -s.wi);
    s.pdf = 1.0;
    s.delta = true;
    s.valid = true;
    return s;
}

// LightSampler::evalHit: does origin + t dir, t in (0, tMax), find the light's emission?
// escaped: the ray left the scene (the CPU's tMax = infinity), the only way to see the sun.
bool lightEvalHit(Light l, vec3 origin, vec3 dir, float tMax, bool escaped, out float tHit) {
    tHit = 0.0;
    if (lightIsDelta(l)) return false;
    uint type = lightType(l);
    vec3 pos = l.positionType.xyz;
    vec3 n = l.normalRadius.xyz;
    if (type == kLightSphere) {
        vec3 toCentre = pos - origin;
        float r = l.normalRadius.w;
        float d2 = dot(toCentre, toCentre), r2 = r * r;
        if (!(d2 > r2)) return false;
        float b = dot(toCentre, dir);
        vec3 perp = toCentre - b * dir;
        float h2 = r2 - dot(perp, perp);
        if (b <= 0.0 || h2 < r2 * (1.0 - kLightRimSlack2)) return false;
        float t = b - sqrt(max(0.0, h2));
        if (!(t > 0.0 && (escaped || t < tMax))) return false;
        tHit = t;
        return true;
    }
    if (type == kLightRect) {
        if (!(l.emissionArea.w > 0.0)) return false;
        float facing = dot(dir, n);
        if (!(facing < 0.0)) return false;
        float t = dot(pos - origin, n) / facing;
        if (!(t > 0.0 && (escaped || t < tMax))) return false;
        vec3 local = origin + t * dir - pos;
        vec3 u = l.axisUInner.xyz, v = l.axisVOuter.xyz;
        float a = dot(local, u) / dot(u, u);
        float bb = dot(local, v) / dot(v, v);
        if (abs(a) > kLightEdgeSlack || abs(bb) > kLightEdgeSlack) return false;
        tHit = t;
        return true;
    }
    if (type == kLightSun) {
        if (!escaped) return false;
        vec3 toSun = -n;
        vec3 c = cross(dir, toSun);
        if (dot(dir, toSun) <= 0.0 || dot(c, c) > l.sun.x * kLightRimSlack2) return false;
        tHit = kFloatMax;
        return true;
    }
    return false;
}

// LightSampler::pdf: solid-angle density of lightSample at wi from p; 0 for delta lights.
float lightPdf(Light l, vec3 p, vec3 wi) {
    if (lightIsDelta(l)) return 0.0;
    uint type = lightType(l);
    vec3 pos = l.positionType.xyz;
    vec3 n = l.normalRadius.xyz;
    if (type == kLightSphere) {
        vec3 toCentre = pos - p;
        float r = l.normalRadius.w;
        float d2 = dot(toCentre, toCentre), r2 = r * r;
        if (!(d2 > r2)) return 0.0;
        float b = dot(toCentre, wi);
        vec3 perp = toCentre - b * wi;
        if (b <= 0.0 || dot(perp, perp) > r2 * kLightRimSlack2) return 0.0;
        return lightConePdf(sphereOneMinusCos(r2, d2));
    }
    if (type == kLightRect) {
        float t;
        if (!lightEvalHit(l, p, wi, kFloatMax, true, t)) return 0.0;
        SphericalRect sr = lightSphericalRect(l, p);
        if (sr.solidAngle >= kMinSphericalRectSolidAngle) return 1.0 / sr.solidAngle;
        return t * t / (l.emissionArea.w * -dot(wi, n));
    }
    if (type == kLightSun) {
        vec3 toSun = -n;
        vec3 c = cross(wi, toSun);
        if (dot(wi, toSun) <= 0.0 || dot(c, c) > l.sun.x * kLightRimSlack2) return 0.0;
        return lightConePdf(l.sun.y);
    }
    return 0.0;
}

#endif
