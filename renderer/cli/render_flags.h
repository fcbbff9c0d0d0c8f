// The render flags shared by `render` and `bench` (architecture.md §6): --width --height --seed
// --bounces --device --sampler, with defaults from the scene's render settings.
#pragma once

#include "cli/args.h"
#include "render/session/render_options.h"
#include "scene/scene.h"
#include "util/result.h"

#include <set>
#include <string>

namespace wavelit::cli {

// Value flags understood by renderOptionsFromArgs.
const std::set<std::string>& renderValueFlags();

util::Result<render::RenderOptions> renderOptionsFromArgs(const Args& args,
                                                          const scene::RenderDefaults& defaults);

} // namespace wavelit::cli
