#include "model/model_file_checks.h"

#include <cstdint>
#include <cstring>

std::optional<std::string> glbFramingProblem(std::string_view bytes) {
    auto word = [&](std::size_t at) {
        std::uint32_t value = 0;
        std::memcpy(&value, bytes.data() + at, 4);
        return value;
    };
    if (bytes.size() < 20) return "a GLB file shorter than its 12-byte header and a chunk";
    if (word(8) != bytes.size())
        return "the GLB header gives a length of " + std::to_string(word(8)) +
               " bytes; the file has " + std::to_string(bytes.size());
    std::size_t at = 12;
    while (at < bytes.size()) {
        if (bytes.size() - at < 8)
            return "a GLB chunk header cut short at byte " + std::to_string(at);
        const std::uint64_t length = word(at);
        if (length > bytes.size() - at - 8)
            return "the GLB chunk at byte " + std::to_string(at) + " claims " +
                   std::to_string(length) + " bytes; " + std::to_string(bytes.size() - at - 8) +
                   " follow";
        at += 8 + length;
    }
    return std::nullopt;
}
