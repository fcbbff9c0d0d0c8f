#include "wavelet/sphere_sampler.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace wavelit::wavelet {

util::Result<SphereSampler> SphereSampler::build(const SphereMap& map,
                                                 const std::vector<SquareGrid>& faces) {
    if (int(faces.size()) != map.faceCount())
        return util::makeError(util::ErrorKind::Invalid, "", "one grid per face is needed");
    SphereSampler s;
    s.m_map = &map;
    double total = 0.0;
    std::vector<double> mass;
    for (int f = 0; f < map.faceCount(); ++f) {
        const SquareGrid& g = faces[size_t(f)];
        if (auto finite = checkFinite(g); !finite)
            return finite.error();
        // Function x (texel solid angle / texel area): the square density that follows the
        // function per solid angle.
        SquareGrid weighted(g.level);
        const double texelsPerArea = std::ldexp(1.0, 2 * g.level);
        for (int y = 0; y < g.size(); ++y)
            for (int x = 0; x < g.size(); ++x)
                weighted.at(x, y) =
                    g.at(x, y) * map.texelSolidAngle(f, g.level, x, y) * texelsPerArea;
        auto sampler = HierarchicalSampler::build(ScalingTree::fromGrid(weighted));
        if (sampler) {
            mass.push_back(sampler->clampedIntegral());
            s.m_faces.emplace_back(std::move(*sampler));
        } else {
            mass.push_back(0.0);
            s.m_faces.emplace_back(std::nullopt);
        }
        total += mass.back();
    }
    if (!(total > 0.0))
        return util::makeError(util::ErrorKind::Invalid, "",
                               "all-zero function: nothing to sample");
    for (double m : mass)
        s.m_faceProbability.push_back(m / total);
    return s;
}

DirectionSample SphereSampler::sample(glm::dvec2 u) const {
    // Face by u.x, rescaled; a face with probability 0 is never chosen.
    int face = 0;
    double start = 0.0;
    for (; face + 1 < int(m_faceProbability.size()); ++face) {
        if (m_faceProbability[size_t(face)] > 0.0 && u.x < start + m_faceProbability[size_t(face)])
            break;
        start += m_faceProbability[size_t(face)];
    }
    while (m_faceProbability[size_t(face)] == 0.0)
        --face; // rounding pushed u past the last face
    u.x = std::clamp((u.x - start) / m_faceProbability[size_t(face)], 0.0, 0x1.fffffffffffffp-1);
    const SquareSample s = m_faces[size_t(face)]->sample(u);
    DirectionSample out;
    out.direction = m_map->toDirection(face, s.point);
    out.pdf = m_faceProbability[size_t(face)] * s.pdf / m_map->jacobian(face, s.point);
    return out;
}

double SphereSampler::pdf(glm::dvec3 direction) const {
    const FacePoint p = m_map->toSquare(direction);
    const auto& face = m_faces[size_t(p.face)];
    if (!face)
        return 0.0;
    const glm::dvec2 uv = glm::min(p.uv, glm::dvec2(0x1.fffffffffffffp-1));
    return m_faceProbability[size_t(p.face)] * face->pdf(uv) / m_map->jacobian(p.face, uv);
}

} // namespace wavelit::wavelet
