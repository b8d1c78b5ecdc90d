#include "gpu/shader_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <glslang/build_info.h>

#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>

namespace {

// glslang needs one process-wide initialisation before any compile.
void initializeGlslangOnce() {
    static std::once_flag once;
    std::call_once(once, [] {
        glslang::InitializeProcess();
        std::atexit([] { glslang::FinalizeProcess(); });
    });
}

// Serves #include "name" from the loader. Included text lives as long as the includer.
class MemoryIncluder : public glslang::TShader::Includer {
  public:
    explicit MemoryIncluder(const ShaderSourceLoader& load) : load_(load) {}

    IncludeResult* includeLocal(const char* name, const char*, size_t) override {
        std::optional<std::string> text = load_(name);
        if (!text) return nullptr; // glslang reports "cannot find include file"
        texts_.push_back(std::make_unique<std::string>(std::move(*text)));
        return new IncludeResult(name, texts_.back()->data(), texts_.back()->size(), nullptr);
    }
    IncludeResult* includeSystem(const char* name, const char* includer, size_t depth) override {
        return includeLocal(name, includer, depth);
    }
    void releaseInclude(IncludeResult* result) override { delete result; }

  private:
    const ShaderSourceLoader& load_;
    std::vector<std::unique_ptr<std::string>> texts_;
};

} // namespace

std::vector<std::uint32_t> compileComputeShader(const std::string& mainFile,
                                                const ShaderSourceLoader& load,
                                                const std::string& preamble) {
    initializeGlslangOnce();
    std::optional<std::string> source = load(mainFile);
    if (!source) throw ShaderCompileError("shader source '" + mainFile + "' not found");

    glslang::TShader shader(EShLangCompute);
    const char* text = source->c_str();
    const int length = static_cast<int>(source->size());
    const char* name = mainFile.c_str();
    shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
    if (!preamble.empty()) shader.setPreamble(preamble.c_str());
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);

    MemoryIncluder includer(load);
    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 460, false, messages, includer))
        throw ShaderCompileError("shader compilation failed:\n" + std::string(shader.getInfoLog()));

    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages))
        throw ShaderCompileError("shader linking failed:\n" + std::string(program.getInfoLog()));

    std::vector<std::uint32_t> spirv;
    spv::SpvBuildLogger logger;
    glslang::SpvOptions options;
    options.disableOptimizer = false;
    glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), spirv, &logger, &options);
    std::string log = logger.getAllMessages();
    if (spirv.empty()) throw ShaderCompileError("SPIR-V generation failed:\n" + log);
    return spirv;
}

// Bump the "v" when the settings of compileComputeShader above change.
std::string glslangVersion() {
    return std::to_string(GLSLANG_VERSION_MAJOR) + "." + std::to_string(GLSLANG_VERSION_MINOR) +
           "." + std::to_string(GLSLANG_VERSION_PATCH);
}

std::string shaderCompilerRecipe() {
    return "glslang " + glslangVersion() + "; vulkan1.2 spv1.5 optimized; v1";
}

ShaderSourceLoader directoryShaderLoader(const std::filesystem::path& directory) {
    return [directory](const std::string& name) -> std::optional<std::string> {
        // Bare names only: an include cannot reach outside the folder.
        if (name.empty() || name.find('/') != std::string::npos || name == "." || name == "..")
            return std::nullopt;
        std::ifstream file(directory / name, std::ios::binary);
        if (!file) return std::nullopt;
        std::ostringstream text;
        text << file.rdbuf();
        return text.str();
    };
}
