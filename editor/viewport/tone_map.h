// Display tone mapping of a linear render: scale by 2^EV (Camera::exposureEv), clamp to [0, 1],
// encode with the sRGB transfer function, quantise to 8 bits. A display step only: it reads the
// accumulated mean image and never touches accumulation (architecture.md §5.B), so changing exposure
// re-maps the last frame instead of restarting the render.
#pragma once

#include "util/image.h"

#include <QImage>

namespace wavelit::editor {

// sRGB-encoded 8-bit value of a linear value in [0, 1] (IEC 61966-2-1 piecewise curve).
// Non-finite and negative inputs map to 0, values above 1 to 255.
int linearToSrgb8(float linear);

// Row 0 of the image is the top row of the result. Format_RGB32. An empty image gives a null QImage.
QImage toneMap(const util::ImageRGB& image, float exposureEv);

} // namespace wavelit::editor
