// The direction samplers' constants and table layouts as GLSL #defines (issue 11): the shaders in
// shaders/sampling/ hold no copy of a number the C++ samplers use; every pipeline that compiles
// them (the path tracer, the sampler probe in render/testing/) appends these to its defines.
// Sources: render/sampling/sampler_constants.h (mixture and refinement constants),
// sampling/product/flat_product_layout.h (the flat tables), gpu_sampler_data.h (what the GPU forms
// per hit, the material modes), render_options.h (the kind codes), sampler_window.h.
#pragma once

#include <string>
#include <vector>

namespace wavelit::render {

// "NAME=VALUE" strings (vk::ShaderCompileOptions::defines); doubles end in LF, floats are
// written with enough digits to round-trip.
std::vector<std::string> samplerShaderDefines();

} // namespace wavelit::render
