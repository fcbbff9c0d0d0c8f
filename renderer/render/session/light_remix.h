// LightMix remix (docs/lightmix.md): the weights that turn the light-group layers of a render of
// one scene into the image of another that differs from it only in what a weight can express —
// a light's intensity, colour or mute, the environment's intensity — so an editor can show such an
// edit by recombining the layers it has, on the next frame, instead of restarting the render.
// The estimator's draws do not depend on these (docs/estimator.md "Light groups"), so the passes
// that follow sample exactly as a fresh render of the edited scene would.
#pragma once

#include "render/session/light_groups.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace wavelit::render {

// Per group of lightGroupsOf(rendered): shown's emitted radiance over rendered's, per channel.
// nullopt (the render must restart) when anything else differs, when a group's lights changed by
// different factors, or when a light or the environment that `shown` lights was black in
// `rendered` (no layer to scale: a light rendered muted or at zero, a channel of its colour at 0).
// The environment's tint is not remixed: its sampling tables follow the tint's luminance.
std::optional<std::vector<glm::vec3>> remixWeights(const scene::Scene& rendered,
                                                   const scene::Scene& shown);

// The scene an editor renders for `shown` when remixing: every light unmuted (a muted light's
// layer must exist so unmuting is a remix too; its weight is then 0).
scene::Scene remixBaseScene(const scene::Scene& shown);

} // namespace wavelit::render
