// Runtime GLSL -> SPIR-V compilation with glslang, so shaders and BRDF snippets (plugins/*.glsl)
// can be edited without rebuilding and a compile error is a message, not a crash.
//
// `#include "name"` (GL_GOOGLE_include_directive) is resolved against the including file's folder,
// then each of includeDirs in order. Errors are ErrorKind::Format naming the file (the included
// file when the error is inside one) and "line N", with glslang's reason; a missing file is
// NotFound. Thread-safe: glslang is initialised once per process.
#pragma once

#include "util/result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wavelit::vk {

struct ShaderCompileOptions {
    std::vector<std::string> includeDirs;
    std::vector<std::string> defines; // "NAME" or "NAME=VALUE"
};

// Compiles a compute shader from a file.
util::Result<std::vector<uint32_t>> compileComputeShaderFile(const std::string& path,
                                                             const ShaderCompileOptions& options);

// Compiles a compute shader from source text; `name` is the file name used in messages and the
// folder searched first for includes.
util::Result<std::vector<uint32_t>> compileComputeShader(const std::string& source,
                                                         const std::string& name,
                                                         const ShaderCompileOptions& options);

} // namespace wavelit::vk
