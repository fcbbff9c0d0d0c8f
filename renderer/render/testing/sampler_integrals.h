// Dense integration of the environment-lighting integrand for sampler tests and the variance
// study (issue 6; architecture.md §4.1's deterministic study, §8 "mean of f/p equals the integral").
//
// The integrand is g(w) = luminance(f(wo, w) cos(theta) L(w)) with L the environment exactly as
// the tracers evaluate it: the NEAREST equirect texel (cpu_environment.h). L is constant on each
// texel, so the sphere is integrated texel by texel: each texel is cut into sub x sub cells equal
// in solid angle (uniform in phi and cos(theta)), integrated by the midpoint rule; texels within
// `hotRadius` of a hot spot (the reflection vector of a narrow lobe) use hotSub x hotSub cells.
// Then for any sampler pdf p (solid angle): I = sum g dw, the estimator's second moment
// sum g^2 / p dw, and its exact per-sample variance Var = second moment - I^2 (the study's
// "Var = integral f^2/p - I^2"). Points where g > 0 but p = 0 make the estimator biased: they are
// reported as uncoveredIntegral (and the variance is then infinite).
// Not thread-safe to build; moments() is const and thread-safe.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <functional>
#include <limits>
#include <vector>

namespace wavelit::render {

struct EstimatorMoments {
    double integral = 0.0;
    double secondMoment = 0.0;
    double uncoveredIntegral = 0.0; // part of I where p = 0
    double variance() const {
        return uncoveredIntegral > 0.0 ? std::numeric_limits<double>::infinity()
                                       : secondMoment - integral * integral;
    }
};

struct DenseIntegrandOptions {
    int sub = 2;
    int hotSub = 48;
    std::vector<glm::vec3> hotSpots; // world directions
    double hotRadius = 0.0;          // radians
    int constantEnvWidth = 128;      // texel grid used when the env has no image
};

class DenseIntegrand {
public:
    // brdfCos(wi): f(wo, wi) cos(theta_i) as RGB for a world direction.
    DenseIntegrand(const scene::Environment& env,
                   const std::function<glm::vec3(const glm::vec3&)>& brdfCos,
                   const DenseIntegrandOptions& options = {});

    double integral() const { return m_integral; }
    EstimatorMoments moments(const std::function<double(const glm::vec3&)>& pdf) const;
    size_t pointCount() const { return m_dirs.size(); }

private:
    std::vector<glm::vec3> m_dirs; // only points with g > 0
    std::vector<double> m_g;       // integrand value
    std::vector<double> m_dw;      // solid angle
    double m_integral = 0.0;
};

} // namespace wavelit::render
