// The BRDF dispatch generated from the plugin registry (brdf_shader_source.h): one case per
// plugin with a GLSL twin, compile errors keep the kernel's own line numbers, and a kernel that
// includes common/brdf.glsl without the dispatch fails with the reason.
#include "render/gpu/brdf_shader_source.h"

#include "plugins/brdf.h"
#include "render/gpu/gpu_path_tracer.h"
#include "render/gpu/gpu_scene_data.h"

#include <gtest/gtest.h>

#include <string>

namespace wavelit::render {
namespace {

vk::ShaderCompileOptions includeDirs() { return {{gpuShaderDirectory(), gpuPluginDirectory()}, {}}; }

TEST(BrdfShaderSource, OneCasePerRegisteredPluginOnItsTypeCode) {
    const std::string glsl = brdfDispatchGlsl();
    for (const plugins::Brdf* b : plugins::brdfRegistry()) {
        const plugins::BrdfGpuTwin t = b->gpuTwin();
        const std::string code = "if (type == " + std::to_string(gpuBrdfType(*b)) + "u) return ";
        EXPECT_NE(glsl.find(std::string("#include \"") + t.snippet + "\""), std::string::npos);
        EXPECT_NE(glsl.find(code + t.sampleFn + "("), std::string::npos) << b->name();
        EXPECT_NE(glsl.find(code + t.evalFn + "("), std::string::npos) << b->name();
        EXPECT_NE(glsl.find(code + t.pdfFn + "("), std::string::npos) << b->name();
    }
}

TEST(BrdfShaderSource, CompilesAndKeepsTheKernelsLineNumbers) {
    const std::string head = "#version 460\n#extension GL_GOOGLE_include_directive : require\n"
                             "#include \"common/brdf.glsl\"\nlayout(local_size_x = 1) in;\n";
    auto good = compileWithBrdfDispatch(
        head + "void main() { vec3 f = brdfEval(0u, vec3(1.0), 0.5, vec3(0, 0, 1), vec3(0, 0, 1)); }\n",
        "good.comp", includeDirs());
    ASSERT_TRUE(good.ok()) << good.error().message();
    auto bad = compileWithBrdfDispatch(head + "void main() {\n    int x = notDeclared;\n}\n",
                                       "bad.comp", includeDirs());
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().where, "line 6") << bad.error().message();
    EXPECT_NE(bad.error().message().find("notDeclared"), std::string::npos);
}

TEST(BrdfShaderSource, KernelWithoutTheDispatchFailsWithTheReason) {
    auto spirv = vk::compileComputeShader(
        "#version 460\n#extension GL_GOOGLE_include_directive : require\n"
        "#include \"common/brdf.glsl\"\nlayout(local_size_x = 1) in;\nvoid main() {}\n",
        "plain.comp", includeDirs());
    ASSERT_FALSE(spirv.ok());
    EXPECT_NE(spirv.error().message().find("generated from the plugin registry"), std::string::npos)
        << spirv.error().message();
}

} // namespace
} // namespace wavelit::render
