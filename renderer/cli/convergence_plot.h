// Draws RMSE-versus-time curves (log-log) into an image for `wavelit-cli bench`. No text: the
// legend is one colour swatch per curve in the order of the curves; bench.json names them.
#pragma once

#include "util/image.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace wavelit::cli {

struct CurvePoint {
    double seconds = 0.0;
    double error = 0.0;
};

struct Curve {
    std::string name;
    glm::vec3 color{0.0f};
    std::vector<CurvePoint> points;
};

// Fixed colour per sampler name so plots of different runs compare at a glance.
glm::vec3 curveColor(const std::string& name);

util::ImageRGB plotConvergence(const std::vector<Curve>& curves, int width = 640, int height = 400);

} // namespace wavelit::cli
