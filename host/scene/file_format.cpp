#include "scene/file_format.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>

namespace {

bool startsWith(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

// UTF-16 by its byte-order mark, or by ASCII text with a NUL after (LE) or before (BE) every
// character of its first line.
bool isUtf16(std::string_view text) {
    if (startsWith(text, "\xFF\xFE") || startsWith(text, "\xFE\xFF")) return true;
    if (text.size() < 4) return false;
    const std::size_t pairs = std::min<std::size_t>(text.size() / 2, 32);
    int nulFirst = 0, nulSecond = 0;
    for (std::size_t i = 0; i < pairs; ++i) {
        const unsigned char a = static_cast<unsigned char>(text[2 * i]),
                            b = static_cast<unsigned char>(text[2 * i + 1]);
        nulSecond += a != 0 && a < 0x80 && b == 0;
        nulFirst += a == 0 && b != 0 && b < 0x80;
    }
    return nulSecond == int(pairs) || nulFirst == int(pairs);
}

std::string lowerExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

} // namespace

bool isBinaryStl(std::string_view text) {
    if (text.size() < 84) return false;
    std::uint32_t triangles = 0;
    std::memcpy(&triangles, text.data() + 80, 4);
    return 84 + 50 * std::uint64_t(triangles) == text.size();
}

std::optional<OtherFormat> otherFileFormat(std::string_view text) {
    if (isUtf16(text)) return OtherFormat::Utf16Text;
    if (startsWith(text, "ply\n") || startsWith(text, "ply\r\n")) return OtherFormat::Ply;
    if (startsWith(text, "glTF")) return OtherFormat::BinaryGltf;
    if (isBinaryStl(text)) return OtherFormat::Stl;
    const std::string_view head = text.substr(0, 1024);
    if (startsWith(text, "solid") && head.find("facet") != std::string_view::npos)
        return OtherFormat::Stl;
    // JSON holding an "asset" key anywhere (exporters put it first or last).
    const std::size_t first = head.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    if (first != std::string_view::npos && head[first] == '{' &&
        text.find("\"asset\"") != std::string_view::npos)
        return OtherFormat::Gltf;
    return std::nullopt;
}

std::string formatName(OtherFormat format) {
    switch (format) {
    case OtherFormat::Utf16Text:
        return "UTF-16 text";
    case OtherFormat::Ply:
        return "a PLY model";
    case OtherFormat::Stl:
        return "an STL model";
    case OtherFormat::Gltf:
        return "a glTF model";
    case OtherFormat::BinaryGltf:
        return "a binary glTF model (.glb)";
    }
    return "another format";
}

std::string otherFormatMessage(OtherFormat format, const std::string& fileName,
                               ExpectedFile expected) {
    const bool obj = expected == ExpectedFile::SourceModel;
    const std::string readAs = obj ? "an OBJ model" : "a scene file";
    if (format == OtherFormat::Utf16Text)
        return "the file is UTF-16 text, and " + readAs +
               " is read as UTF-8; convert it first: iconv -f UTF-16 -t UTF-8 '" + fileName +
               "' > converted" + (obj ? ".obj" : ".scene");
    return "not " + readAs + ": this is " + formatName(format) +
           ", which is not read; convert it to OBJ first (for example with assimp export, "
           "Debian's assimp-utils)";
}

bool isObjPath(const std::filesystem::path& path) {
    return lowerExtension(path) == ".obj";
}

bool isPlyPath(const std::filesystem::path& path) {
    return lowerExtension(path) == ".ply";
}

bool isStlPath(const std::filesystem::path& path) {
    return lowerExtension(path) == ".stl";
}

bool isAssimpPath(const std::filesystem::path& path) {
    const std::string extension = lowerExtension(path);
    for (const char* known : {".gltf", ".glb", ".fbx", ".dae", ".3ds", ".off"})
        if (extension == known) return true;
    return false;
}

bool isModelPath(const std::filesystem::path& path) {
    return isObjPath(path) || isPlyPath(path) || isStlPath(path) || isAssimpPath(path);
}
