// A digest of what a scene renders: every registry property that changes the image (not the
// Display ones: names, exposure), in entity order, plus the loaded assets themselves (mesh
// vertices and indices, environment texels) instead of their paths. Two machines that load the
// same scene from different folders get the same digest; a moved light, another roughness or an
// edited environment map gives another. `wavelit-cli merge` refuses parts whose digests differ
// (docs/farm.md). Not a cryptographic hash: it catches mistakes, not forgeries.
#pragma once

#include "scene/scene.h"

#include <string>

namespace wavelit::scene {

// 16 lowercase hex digits (64-bit FNV-1a over the fields above).
std::string sceneDigest(const Scene& scene);

} // namespace wavelit::scene
