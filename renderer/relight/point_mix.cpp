// mixTerms (point_transfer.h): a preview point's radiance from its cached terms, at the current
// environment scale and light powers, with the material's colour mixed in per ColourUse.
#include "relight/point_transfer.h"

namespace wavelit::relight {
namespace {

// PointState and PointTerms alike (the same sums in the same order).
template <class Terms>
glm::vec3 mixWith(const ResolvedMaterial& m, const Terms& s, const glm::vec3& envScale,
                  const std::vector<glm::vec3>& lightPowers) {
    glm::vec3 white = s.envTerm * envScale;
    for (size_t k = 0; k < s.lightTerms.size(); ++k) white += s.lightTerms[k] * lightPowers[k];
    switch (m.colourUse) {
    case ColourUse::Linear: return m.baseColor * white;
    case ColourUse::Affine: {
        glm::vec3 black = s.envTerm0 * envScale;
        for (size_t k = 0; k < s.lightTerms0.size(); ++k) black += s.lightTerms0[k] * lightPowers[k];
        return black + m.baseColor * (white - black);
    }
    case ColourUse::Fixed:
    case ColourUse::Ignored: break;
    }
    return white;
}

} // namespace

glm::vec3 mixTerms(const ResolvedMaterial& m, const PointState& s, const glm::vec3& envScale,
                   const std::vector<glm::vec3>& lightPowers) {
    return mixWith(m, s, envScale, lightPowers);
}

glm::vec3 mixTerms(const ResolvedMaterial& m, const PointTerms& t, const glm::vec3& envScale,
                   const std::vector<glm::vec3>& lightPowers) {
    return mixWith(m, t, envScale, lightPowers);
}

} // namespace wavelit::relight
