// 8-bit RGBA images and PNG files (stb). No Vulkan, so the reference renderer and
// the tests can use it without a GPU.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

// Row-major, top row first, 4 bytes per pixel (R, G, B, A).
struct Image8 {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

// Reads any PNG stb understands and expands it to RGBA8.
// Throws std::runtime_error "PATH: REASON" if it can't.
Image8 readPng(const std::filesystem::path& path);

// Reads a PNG, a JPEG or a binary PPM (stb tells them by their first bytes) as RGBA8.
// Throws std::runtime_error "PATH: REASON" if it can't.
Image8 readImage8(const std::filesystem::path& path);

// Decodes a PNG, JPEG, BMP or TGA file's bytes (PATH only names it in errors) as RGBA8;
// a PNM file is refused. The size in
// its header is checked first: over maxSide pixels a side is an error before any pixel
// memory is reserved. Throws std::runtime_error "PATH: REASON".
Image8 decodeImage8(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes,
                    int maxSide);

// The bytes of a file of each 8-bit format (PATH only names the file in an error): PNG;
// baseline JPEG at quality 1 to 100 (stb); binary PPM ("P6", 8-bit RGB). Alpha is dropped
// by JPEG and PPM; the renderer's is always 255.
std::vector<std::uint8_t> encodePng(const std::filesystem::path& path, const Image8& image);
std::vector<std::uint8_t> encodeJpeg(const std::filesystem::path& path, const Image8& image,
                                     int quality);
std::vector<std::uint8_t> encodePpm(const std::filesystem::path& path, const Image8& image);

// Writes all of bytes to stdout (-o -), every write checked. Throws std::runtime_error.
void writeStandardOutput(const std::vector<std::uint8_t>& bytes);

// Writes "PATH.tmp" and renames it over PATH, so a failed write never leaves a
// truncated PNG behind. Throws std::runtime_error "PATH: REASON" on failure.
void writePng(const std::filesystem::path& path, const Image8& image);

// The same for any file's bytes (writePng and the float images use it): "PATH.tmp", every
// write checked, then renamed over PATH. Throws std::runtime_error "PATH: REASON".
void writeFileReplacing(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);

// Checks before any rendering that PATH can be written, by creating "PATH.tmp"
// (empty; writePng replaces it). Throws std::runtime_error "PATH: REASON" when the
// folder is missing or not writable, or PATH is a folder. An existing PATH is untouched.
void reservePngOutput(const std::filesystem::path& path);

// Removes "PATH.tmp" left by reservePngOutput (a failed or interrupted run).
void releasePngOutput(const std::filesystem::path& path);
