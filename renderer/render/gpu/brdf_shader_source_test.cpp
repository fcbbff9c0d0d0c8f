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
    // The dispatch switches on the plugin index, the type code modulo kBrdfTypeCodePlugins; a twin
    // with a type parameter gets it decoded as its first argument (plugins/brdf.h).
    const std::string glsl = brdfDispatchGlsl();
    EXPECT_NE(glsl.find("uint plugin = type % 256u;"), std::string::npos);
    for (const plugins::Brdf* b : plugins::brdfRegistry()) {
        const plugins::BrdfGpuTwin t = b->gpuTwin();
        const std::string code = "if (plugin == " + std::to_string(gpuBrdfType(*b)) + "u) return ";
        if (!plugins::brdfGpuTwinProblem(*b).empty()) {
            EXPECT_EQ(glsl.find(code), std::string::npos) << b->name() << " has no twin, so no case";
            continue;
        }
        const std::string first = t.typeParameter ? "brdfTypeParameter(type), " : "";
        EXPECT_NE(glsl.find(std::string("#include \"") + t.snippet + "\""), std::string::npos);
        EXPECT_NE(glsl.find(code + t.sampleFn + "(" + first), std::string::npos) << b->name();
        EXPECT_NE(glsl.find(code + t.evalFn + "(" + first), std::string::npos) << b->name();
        EXPECT_NE(glsl.find(code + t.pdfFn + "(" + first), std::string::npos) << b->name();
    }
}

// A kernel compiled for a scene carries only its materials' plugins: their includes and cases,
// none of the others'.
TEST(BrdfShaderSource, APluginSetCompilesOnlyItsTwins) {
    const plugins::Brdf& ggx = *plugins::findBrdf("ggx");
    const plugins::Brdf& lambert = *plugins::findBrdf("lambert");
    const BrdfPluginSet set = (BrdfPluginSet(1) << gpuBrdfType(ggx)) | (BrdfPluginSet(1) << gpuBrdfType(lambert));
    const std::string glsl = brdfDispatchGlsl(set);
    for (const plugins::Brdf* b : plugins::brdfRegistry()) {
        if (!plugins::brdfGpuTwinProblem(*b).empty())
            continue;
        const bool wanted = b == &ggx || b == &lambert;
        const std::string include = std::string("#include \"") + b->gpuTwin().snippet + "\"";
        const std::string code = "if (plugin == " + std::to_string(gpuBrdfType(*b)) + "u) return ";
        EXPECT_EQ(glsl.find(include) != std::string::npos, wanted) << b->name();
        EXPECT_EQ(glsl.find(code) != std::string::npos, wanted) << b->name();
    }
    const std::string kernel = "#version 460\n#extension GL_GOOGLE_include_directive : require\n"
                               "#include \"common/brdf.glsl\"\nlayout(local_size_x = 1) in;\n"
                               "layout(std430, binding = 0) buffer Out { vec4 o[]; };\n"
                               "void main() { o[0].xyz = brdfEval(0u, vec3(1.0), 0.5, vec3(0, 0, 1), vec3(0, 0, 1)); }\n";
    auto spirv = compileWithBrdfDispatch(kernel, "two_plugins.comp", includeDirs(), set);
    EXPECT_TRUE(spirv.ok()) << spirv.error().message();
}

// A plugin that reads a table (`measured`) is included and dispatched only where the kernel binds
// the tables buffer (kBrdfTableBindingDefine); a kernel that does not still compiles, without it.
TEST(BrdfShaderSource, TablePluginsOnlyWhereTheKernelBindsTheTables) {
    const std::string glsl = brdfDispatchGlsl();
    const plugins::Brdf& measured = *plugins::findBrdf("measured");
    const std::string guard = std::string("#ifdef ") + kBrdfTableBindingDefine + "\n";
    EXPECT_NE(glsl.find(guard + "#include \"" + measured.gpuTwin().snippet + "\""), std::string::npos) << glsl;
    EXPECT_NE(glsl.find(guard + "    if (plugin == " + std::to_string(gpuBrdfType(measured)) + "u) return " +
                        measured.gpuTwin().evalFn + "("),
              std::string::npos)
        << glsl;
    const std::string kernel = "#version 460\n#extension GL_GOOGLE_include_directive : require\n"
                               "#include \"common/brdf.glsl\"\nlayout(local_size_x = 1) in;\n"
                               "layout(std430, binding = 0) buffer Out { vec4 o[]; };\n"
                               "void main() { o[0].xyz = brdfEval(" + std::to_string(gpuBrdfType(measured)) +
                               "u, vec3(1.0), 0.0, vec3(0, 0, 1), vec3(0, 0, 1)); }\n";
    vk::ShaderCompileOptions withTables = includeDirs();
    withTables.defines.push_back(std::string(kBrdfTableBindingDefine) + "=1");
    auto bound = compileWithBrdfDispatch(kernel, "tables.comp", withTables);
    EXPECT_TRUE(bound.ok()) << bound.error().message();
    auto unbound = compileWithBrdfDispatch(kernel, "no_tables.comp", includeDirs());
    EXPECT_TRUE(unbound.ok()) << unbound.error().message();
}

// A type parameter rides above the plugin index in steps of 1/4096, exact in the float the
// material buffer stores it in; the plugin rounds the value the same way.
TEST(BrdfShaderSource, TypeParameterPacksAboveThePluginIndex) {
    const plugins::Brdf& ward = *plugins::findBrdf("ward");
    const uint32_t index = gpuBrdfType(ward);
    EXPECT_EQ(gpuBrdfType(ward, plugins::BrdfParams(glm::vec3(1.0f), 0.3f, 0.0f)), index);
    EXPECT_EQ(gpuBrdfType(ward, plugins::BrdfParams(glm::vec3(1.0f), 0.3f, 0.5f)), index + 256u * 2048u);
    const uint32_t full = gpuBrdfType(ward, plugins::BrdfParams(glm::vec3(1.0f), 0.3f, 1.0f));
    EXPECT_EQ(full, index + 256u * 4096u);
    EXPECT_EQ(uint32_t(float(full)), full);
    EXPECT_FLOAT_EQ(plugins::brdfTypeParameterStep(0.30001f), 1229.0f / 4096.0f);
    // Plugins without one keep the bare index whatever the material's anisotropy.
    const plugins::Brdf& ggx = *plugins::findBrdf("ggx");
    EXPECT_EQ(gpuBrdfType(ggx, plugins::BrdfParams(glm::vec3(1.0f), 0.3f, 0.7f)), gpuBrdfType(ggx));
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
