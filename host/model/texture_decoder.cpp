#include "model/texture_decoder.h"

#include "model/contained_reader.h"
#include "scene/scene_error.h"

#include <cstring>
#include <stdexcept>

namespace {

// The child's answer, a record per file: 'I', width and height (uint32 each) and the
// RGBA8 bytes; or 'E', the length of a message (uint64) and the message.
template <typename T> void append(std::string& out, T value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

std::string decodedBytes(const std::vector<TextureBytes>& files, int maxSide) {
    std::string out;
    for (const TextureBytes& file : files) {
        try {
            const Image8 image = decodeImage8(file.file, file.bytes, maxSide);
            out.push_back('I');
            append(out, std::uint32_t(image.width));
            append(out, std::uint32_t(image.height));
            out.append(reinterpret_cast<const char*>(image.rgba.data()), image.rgba.size());
        } catch (const std::exception& error) {
            const std::string message = error.what();
            out.push_back('E');
            append(out, std::uint64_t(message.size()));
            out += message;
        }
    }
    return out;
}

template <typename T> T take(const std::string& bytes, std::size_t& at) {
    T value{};
    if (bytes.size() - at < sizeof value) throw std::runtime_error("cut short");
    std::memcpy(&value, bytes.data() + at, sizeof value);
    at += sizeof value;
    return value;
}

std::vector<DecodedTexture> fromBytes(const std::string& bytes, std::size_t count, int maxSide) {
    std::vector<DecodedTexture> decoded(count);
    std::size_t at = 0;
    for (DecodedTexture& texture : decoded) {
        const char kind = take<char>(bytes, at);
        if (kind == 'I') {
            Image8 image;
            image.width = int(take<std::uint32_t>(bytes, at));
            image.height = int(take<std::uint32_t>(bytes, at));
            if (image.width <= 0 || image.height <= 0 || image.width > maxSide ||
                image.height > maxSide)
                throw std::runtime_error("an image of a size out of range");
            const std::size_t size = std::size_t(image.width) * std::size_t(image.height) * 4;
            if (bytes.size() - at < size) throw std::runtime_error("cut short");
            image.rgba.assign(bytes.begin() + std::ptrdiff_t(at),
                              bytes.begin() + std::ptrdiff_t(at + size));
            at += size;
            texture.image = std::move(image);
        } else if (kind == 'E') {
            const auto length = take<std::uint64_t>(bytes, at);
            if (bytes.size() - at < length) throw std::runtime_error("cut short");
            texture.problem = bytes.substr(at, length);
            at += length;
        } else {
            throw std::runtime_error("an unknown record");
        }
    }
    if (at != bytes.size()) throw std::runtime_error("bytes left over");
    return decoded;
}

// The files decoded in one child; throws SceneError (named after the first file) when the
// child does not answer.
std::vector<DecodedTexture> decodeInChild(const std::vector<TextureBytes>& files, int maxSide) {
    const std::string answer = runContained(files.front().file, "the texture decoder",
                                            [&] { return decodedBytes(files, maxSide); });
    try {
        return fromBytes(answer, files.size(), maxSide);
    } catch (const std::runtime_error& error) {
        throw SceneError(files.front().file, 0,
                         std::string("the texture decoder's answer is broken: ") + error.what());
    }
}

} // namespace

std::vector<DecodedTexture> decodeTextures(const std::vector<TextureBytes>& files, int maxSide) {
    if (files.empty()) return {};
    try {
        return decodeInChild(files, maxSide);
    } catch (const SceneError&) {
        // One of them crashed the decoder: which, each in a child of its own tells.
    }
    std::vector<DecodedTexture> decoded;
    for (const TextureBytes& file : files) {
        try {
            decoded.push_back(decodeInChild({file}, maxSide).front());
        } catch (const SceneError& error) {
            decoded.push_back({std::nullopt, file.file + ": " + error.message});
        }
    }
    return decoded;
}
