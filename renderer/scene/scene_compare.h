// Model equality through the registry: every property of every entity, plus the structure the
// registry does not describe (ids, entity order, scene/lighting names, lighting reference, extras).
// Loaded assets (meshes, images) are not compared: they follow from the paths. Used by round-trip
// and undo tests, and by anything that needs to know whether an edit changed the document.
#pragma once

#include "scene/scene.h"

#include <string>

namespace wavelit::scene {

// Empty when the models are identical; otherwise a description of the first difference, e.g.
// "material #2 roughness: 0.2 != 0.3".
std::string firstDifference(const Scene& a, const Scene& b);
std::string firstDifference(const LightingSetup& a, const LightingSetup& b);

} // namespace wavelit::scene
