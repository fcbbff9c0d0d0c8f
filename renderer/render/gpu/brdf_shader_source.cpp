#include "render/gpu/brdf_shader_source.h"

#include "plugins/brdf.h"

#include <fstream>
#include <sstream>

namespace wavelit::render {
namespace {

// One `if (plugin == i) return call;` line per plugin with a GLSL twin; a twin that reads a
// type parameter (plugins/brdf.h: BrdfGpuTwin::typeParameter) gets it decoded as its first argument.
// A plugin that reads a data file (`measured`) reads it from the tables buffer, which only kernels
// compiled with kBrdfTableBindingDefine bind: elsewhere it has no case (an invalid sample, f = 0).
// The registry's plugins that have a GLSL twin and are in `plugins`, with their indices.
std::vector<std::pair<size_t, const plugins::Brdf*>> compiledTwins(BrdfPluginSet set) {
    std::vector<std::pair<size_t, const plugins::Brdf*>> out;
    const auto all = plugins::brdfRegistry();
    for (size_t i = 0; i < all.size(); ++i) {
        const bool inSet = i >= 64 || (set >> i) & 1u;
        if (inSet && plugins::brdfGpuTwinProblem(*all[i]).empty())
            out.emplace_back(i, all[i]);
    }
    return out;
}

std::string cases(const char* plugins::BrdfGpuTwin::*fn, const char* args, BrdfPluginSet set) {
    std::string out = "    uint plugin = type % " + std::to_string(plugins::kBrdfTypeCodePlugins) + "u;\n";
    for (const auto& [i, brdf] : compiledTwins(set)) {
        const plugins::BrdfGpuTwin twin = brdf->gpuTwin();
        const bool readsTables = plugins::brdfReadsFile(*brdf);
        if (readsTables)
            out += std::string("#ifdef ") + kBrdfTableBindingDefine + "\n";
        out += "    if (plugin == " + std::to_string(i) + "u) return " + (twin.*fn) + "(" +
               (twin.typeParameter ? "brdfTypeParameter(type), " : "") + args + ");\n";
        if (readsTables)
            out += "#endif\n";
    }
    return out;
}

bool startsWith(const std::string& line, const char* prefix) {
    return line.rfind(prefix, 0) == 0;
}

} // namespace

std::string brdfDispatchGlsl(BrdfPluginSet set) {
    std::string g = "// BRDF dispatch generated from the plugin registry "
                    "(render/gpu/brdf_shader_source.cpp)\n"
                    "#define WAVELIT_BRDF_DISPATCH 1\n"
                    "float brdfTypeParameter(uint type) {\n"
                    "    return float(type / " + std::to_string(plugins::kBrdfTypeCodePlugins) +
                    "u) / " + std::to_string(plugins::kBrdfTypeParameterSteps) + ".0;\n}\n";
    for (const auto& [i, b] : compiledTwins(set)) {
        const bool readsTables = plugins::brdfReadsFile(*b);
        if (readsTables)
            g += std::string("#ifdef ") + kBrdfTableBindingDefine + "\n";
        g += std::string("#include \"") + b->gpuTwin().snippet + "\"\n";
        if (readsTables)
            g += "#endif\n";
    }
    g += "bool brdfSample(uint type, vec3 baseColor, float roughness, vec3 wo, float u1, float u2,\n"
         "                out vec3 wi, out vec3 f, out float pdf) {\n" +
         cases(&plugins::BrdfGpuTwin::sampleFn, "baseColor, roughness, wo, u1, u2, wi, f, pdf", set) +
         "    wi = vec3(0.0, 0.0, 1.0);\n    f = vec3(0.0);\n    pdf = 0.0;\n    return false;\n}\n"
         "vec3 brdfEval(uint type, vec3 baseColor, float roughness, vec3 wo, vec3 wi) {\n" +
         cases(&plugins::BrdfGpuTwin::evalFn, "baseColor, roughness, wo, wi", set) +
         "    return vec3(0.0);\n}\n"
         "float brdfPdf(uint type, float roughness, vec3 wo, vec3 wi) {\n" +
         cases(&plugins::BrdfGpuTwin::pdfFn, "roughness, wo, wi", set) + "    return 0.0;\n}\n";
    return g;
}

std::string spliceBrdfDispatch(const std::string& source, BrdfPluginSet plugins) {
    // A kernel that includes nothing cannot reach common/brdf.glsl; splicing would make it depend
    // on the shader folder the twins include from.
    if (source.find("#include") == std::string::npos)
        return source;
    // The splice goes after the last #extension of the leading directives (GLSL wants extensions
    // before any declaration), or after #version when there is none.
    std::istringstream in(source);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    size_t after = 0; // lines [0, after) precede the splice
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::string& l = lines[i];
        if (startsWith(l, "#version") || startsWith(l, "#extension"))
            after = i + 1;
        else if (!(l.empty() || startsWith(l, "//")))
            break;
    }
    std::string out;
    for (size_t i = 0; i < after; ++i)
        out += lines[i] + "\n";
    out += "#extension GL_GOOGLE_include_directive : require\n" + brdfDispatchGlsl(plugins);
    // GLSL >= 3.30: the line after `#line n` is line n.
    out += "#line " + std::to_string(after + 1) + "\n";
    for (size_t i = after; i < lines.size(); ++i)
        out += lines[i] + "\n";
    return out;
}

util::Result<std::vector<uint32_t>> compileWithBrdfDispatch(const std::string& source,
                                                            const std::string& name,
                                                            const vk::ShaderCompileOptions& options,
                                                            BrdfPluginSet plugins) {
    return vk::compileComputeShader(spliceBrdfDispatch(source, plugins), name, options);
}

util::Result<std::vector<uint32_t>>
compileFileWithBrdfDispatch(const std::string& path, const vk::ShaderCompileOptions& options,
                            BrdfPluginSet plugins) {
    std::ifstream file(path, std::ios::binary);
    if (!file)
        return util::makeError(util::ErrorKind::NotFound, path, "cannot read shader file");
    std::ostringstream text;
    text << file.rdbuf();
    return compileWithBrdfDispatch(text.str(), path, options, plugins);
}

} // namespace wavelit::render
