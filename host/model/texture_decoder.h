// Image files decoded as textures by stb in a child process (contained_reader.h): stb's
// decoders are not hardened against hostile files (the fuzz run found an out-of-bounds
// write in its JPEG reader and a read past the end in its PNM reader), so a file that
// crashes one ends that texture with a message, not the program.
#pragma once

#include "base/image_io.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

// An image file's bytes, and the name it has in messages.
struct TextureBytes {
    std::string file;
    std::vector<std::uint8_t> bytes;
};

// Each file decoded (PNG, JPEG, BMP or TGA, at most maxSide pixels a side, as
// decodeImage8), or why not ("FILE: REASON").
struct DecodedTexture {
    std::optional<Image8> image;
    std::string problem;
};

// All of them in one child; if it crashes, each again in a child of its own, so that only
// the file that crashes it is lost.
std::vector<DecodedTexture> decodeTextures(const std::vector<TextureBytes>& files, int maxSide);
