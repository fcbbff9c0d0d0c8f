// `wavelit-cli render --light-groups` (docs/lightmix.md): the usage checks, the memory said up
// front, and writing the beauty with one layer per light group as a multi-layer EXR
// (scene/exr_layers.h).
#pragma once

#include "cli/args.h"
#include "render/session/render_session.h"
#include "scene/image_io.h"
#include "util/result.h"

#include <string>
#include <vector>

namespace wavelit::cli {

// Usage errors: -o not an EXR; --passes or --mpi (parts and ranks merge the beauty only).
util::Status checkLightGroupFlags(const Args& args, const std::string& output);

// "light groups: 3 layers (sun, environment, emission), 12 bytes a pixel each: 9.0 MiB at
// 512x512 (the CPU reference sums in double: twice that)".
std::string describeLightGroups(const render::LightGroups& groups, int width, int height);

// The session's beauty and group layers, layers named after their groups.
util::Status writeLightGroupExr(const std::string& path, render::RenderSession& session,
                                const util::ImageRGB& beauty,
                                const scene::ExrAttributes& attributes);

} // namespace wavelit::cli
