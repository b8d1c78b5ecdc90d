#include "render/kernel_sources.h"

#include <fstream>
#include <stdexcept>
#include <system_error>

ShaderSourceLoader embeddedShaderLoader() {
    return [](const std::string& name) -> std::optional<std::string> {
        const auto& sources = embeddedShaderSources();
        auto it = sources.find(name);
        if (it == sources.end()) return std::nullopt;
        return std::string(it->second);
    };
}

void writeEmbeddedShaders(const std::filesystem::path& directory) {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
        throw std::runtime_error("cannot create " + directory.string() + ": " + error.message());
    for (const auto& [name, text] : embeddedShaderSources()) {
        const std::filesystem::path path = directory / name;
        std::ofstream file(path, std::ios::binary | std::ios::trunc);
        file.write(text.data(), static_cast<std::streamsize>(text.size()));
        file.close();
        if (!file) throw std::runtime_error("cannot write " + path.string());
    }
}
