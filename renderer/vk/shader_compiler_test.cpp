// glslang runtime compilation: includes resolve, errors name the file and line (also inside an
// included file), a missing file is NotFound.
#include "vk/shader_compiler.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace wavelit::vk {
namespace {

namespace fs = std::filesystem;

const char* kValid = R"(#version 460
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 8) in;
layout(std430, binding = 0) buffer Data { float values[]; };
void main() { values[gl_GlobalInvocationID.x] *= 2.0; }
)";

TEST(ShaderCompiler, CompilesValidShaderToSpirv) {
    auto spirv = compileComputeShader(kValid, "double.comp", {});
    ASSERT_TRUE(spirv.ok()) << spirv.error().message();
    ASSERT_GT(spirv->size(), 5u);
    EXPECT_EQ((*spirv)[0], 0x07230203u); // SPIR-V magic number
}

TEST(ShaderCompiler, ErrorNamesFileAndLine) {
    std::string broken = R"(#version 460
layout(local_size_x = 8) in;
void main() {
    float x = undefinedThing;
}
)";
    auto spirv = compileComputeShader(broken, "broken.comp", {});
    ASSERT_FALSE(spirv.ok());
    EXPECT_EQ(spirv.error().kind, util::ErrorKind::Format);
    EXPECT_EQ(spirv.error().file, "broken.comp");
    EXPECT_EQ(spirv.error().where, "line 4");
    EXPECT_NE(spirv.error().message().find("undefinedThing"), std::string::npos)
        << spirv.error().message();
}

TEST(ShaderCompiler, ResolvesIncludesAndReportsErrorsInsideThem) {
    fs::path dir = fs::temp_directory_path() / "wavelit_shader_compiler_test";
    fs::create_directories(dir / "common");
    std::ofstream(dir / "common" / "twice.glsl") << "float twice(float x) { return 2.0 * x; }\n";
    std::ofstream(dir / "common" / "bad.glsl") << "float bad() {\n  return nope;\n}\n";
    std::string main = R"(#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/twice.glsl"
layout(local_size_x = 8) in;
layout(std430, binding = 0) buffer Data { float values[]; };
void main() { values[gl_GlobalInvocationID.x] = twice(values[gl_GlobalInvocationID.x]); }
)";
    auto ok = compileComputeShader(main, (dir / "main.comp").string(), {});
    EXPECT_TRUE(ok.ok()) << ok.error().message();
    // Found through includeDirs when the including file's folder lacks it.
    auto viaDirs = compileComputeShader(main, "elsewhere.comp", {{dir.string()}, {}});
    EXPECT_TRUE(viaDirs.ok()) << viaDirs.error().message();

    std::string withBad = std::string(main).replace(main.find("twice.glsl"), 10, "bad.glsl");
    auto bad = compileComputeShader(withBad, (dir / "main.comp").string(), {});
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().file.find("bad.glsl"), std::string::npos) << bad.error().message();
    EXPECT_EQ(bad.error().where, "line 2") << bad.error().message();

    std::string missing = std::string(main).replace(main.find("twice.glsl"), 10, "absent.glsl");
    auto absent = compileComputeShader(missing, (dir / "main.comp").string(), {});
    ASSERT_FALSE(absent.ok());
    EXPECT_NE(absent.error().message().find("absent.glsl"), std::string::npos)
        << absent.error().message();
    fs::remove_all(dir);
}

TEST(ShaderCompiler, MissingFileIsNotFound) {
    auto spirv = compileComputeShaderFile("/nonexistent/path.comp", {});
    ASSERT_FALSE(spirv.ok());
    EXPECT_EQ(spirv.error().kind, util::ErrorKind::NotFound);
    EXPECT_EQ(spirv.error().file, "/nonexistent/path.comp");
}

TEST(ShaderCompiler, DefinesReachThePreprocessor) {
    std::string src = R"(#version 460
layout(local_size_x = 8) in;
#if !defined(SCALE) || !defined(FLAG)
#error SCALE and FLAG must be defined
#endif
layout(std430, binding = 0) buffer Data { float values[]; };
void main() { values[gl_GlobalInvocationID.x] *= SCALE; }
)";
    EXPECT_FALSE(compileComputeShader(src, "d.comp", {}).ok());
    auto spirv = compileComputeShader(src, "d.comp", {{}, {"SCALE=3.0", "FLAG"}});
    EXPECT_TRUE(spirv.ok()) << spirv.error().message();
}

} // namespace
} // namespace wavelit::vk
