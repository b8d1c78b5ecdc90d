#include "model/model_paths.h"

#include <filesystem>

namespace {

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// %XX escapes decoded; a '%' not followed by two hex digits stays.
std::string unescaped(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '%' && i + 2 < text.size() && hexDigit(text[i + 1]) >= 0 &&
            hexDigit(text[i + 2]) >= 0) {
            out.push_back(static_cast<char>(hexDigit(text[i + 1]) * 16 + hexDigit(text[i + 2])));
            i += 2;
        } else {
            out.push_back(text[i]);
        }
    }
    return out;
}

} // namespace

std::string directoryOf(const std::string& path) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    return parent.empty() ? std::string() : parent.string();
}

std::string besideFile(const std::string& modelFile, const std::string& name) {
    const std::string folder = directoryOf(modelFile);
    if (folder.empty() || std::filesystem::path(name).is_absolute()) return name;
    return (std::filesystem::path(folder) / name).string();
}

std::string foundFile(const std::string& named) {
    std::error_code error;
    if (std::filesystem::exists(named, error)) return named;
    std::string slashed = named;
    for (char& c : slashed)
        if (c == '\\') c = '/';
    for (const std::string& candidate : {slashed, unescaped(named), unescaped(slashed)})
        if (candidate != named && std::filesystem::exists(candidate, error)) return candidate;
    return named;
}
