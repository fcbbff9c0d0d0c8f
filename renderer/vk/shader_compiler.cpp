#include "vk/shader_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <regex>
#include <sstream>

namespace wavelit::vk {
namespace {

namespace fs = std::filesystem;

std::once_flag g_glslangInit;

bool readText(const fs::path& path, std::string& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return false;
    std::ostringstream ss;
    ss << in.rdbuf();
    out = ss.str();
    return true;
}

class Includer final : public glslang::TShader::Includer {
public:
    explicit Includer(std::vector<std::string> dirs) : m_dirs(std::move(dirs)) {}

    IncludeResult* includeLocal(const char* header, const char* includer, size_t) override {
        std::vector<fs::path> candidates;
        if (includer && *includer)
            candidates.push_back(fs::path(includer).parent_path() / header);
        for (const auto& d : m_dirs)
            candidates.push_back(fs::path(d) / header);
        for (const auto& c : candidates) {
            auto text = std::make_unique<std::string>();
            if (fs::is_regular_file(c) && readText(c, *text)) {
                std::string name = c.lexically_normal().string();
                const char* data = text->data();
                size_t size = text->size();
                return new IncludeResult(name, data, size, text.release());
            }
        }
        m_missing = header;
        return nullptr;
    }
    IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
        return includeLocal(header, includer, depth);
    }
    void releaseInclude(IncludeResult* result) override {
        if (!result)
            return;
        delete static_cast<std::string*>(result->userData);
        delete result;
    }
    const std::string& missing() const { return m_missing; }

private:
    std::vector<std::string> m_dirs;
    std::string m_missing;
};

// glslang logs "ERROR: file:line: 'token' : reason"; the first such line becomes the Error.
util::Error parseLog(const std::string& log, const std::string& fallbackFile) {
    static const std::regex kLine(R"(ERROR: (.+?):(\d+): (.*))");
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_search(line, m, kLine))
            return util::makeError(util::ErrorKind::Format, m[1].str(), m[3].str(),
                                   "line " + m[2].str());
    }
    return util::makeError(util::ErrorKind::Format, fallbackFile,
                           log.empty() ? "compile failed" : log);
}

} // namespace

util::Result<std::vector<uint32_t>> compileComputeShader(const std::string& source,
                                                         const std::string& name,
                                                         const ShaderCompileOptions& options) {
    std::call_once(g_glslangInit, [] { glslang::InitializeProcess(); });

    glslang::TShader shader(EShLangCompute);
    const char* text = source.c_str();
    int length = int(source.size());
    const char* names = name.c_str();
    shader.setStringsWithLengthsAndNames(&text, &length, &names, 1);
    std::string preamble;
    for (const auto& d : options.defines) {
        auto eq = d.find('=');
        preamble += "#define " +
                    (eq == std::string::npos ? d : d.substr(0, eq) + " " + d.substr(eq + 1)) + "\n";
    }
    shader.setPreamble(preamble.c_str());
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);

    Includer includer(options.includeDirs);
    auto messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 460, false, messages, includer)) {
        if (!includer.missing().empty())
            return util::makeError(util::ErrorKind::NotFound, name,
                                   "cannot find included file '" + includer.missing() + "'");
        return parseLog(shader.getInfoLog(), name);
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages))
        return parseLog(program.getInfoLog(), name);

    std::vector<uint32_t> spirv;
    glslang::SpvOptions spv;
    spv.validate = false;
    glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), spirv, &spv);
    if (spirv.empty())
        return util::makeError(util::ErrorKind::Format, name, "SPIR-V generation failed");
    return spirv;
}

util::Result<std::vector<uint32_t>> compileComputeShaderFile(const std::string& path,
                                                             const ShaderCompileOptions& options) {
    std::string source;
    if (!readText(path, source))
        return util::makeError(util::ErrorKind::NotFound, path, "cannot read shader file");
    return compileComputeShader(source, path, options);
}

} // namespace wavelit::vk
