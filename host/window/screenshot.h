// The window's P and Shift+P keys: the output image as it stands, read back and written as
// a PNG under a name that does not overwrite an earlier one.
#pragma once

#include "base/image_io.h"
#include "render/renderer.h"

#include <cstdint>
#include <filesystem>
#include <string>

// Copies the output image (in TRANSFER_SRC_OPTIMAL after a trace) to host memory.
// Waits for the device to be idle first.
Image8 readOutputImage(const Context& context, const Renderer& renderer);

// STEM-screenshot-N-Sspp.png in folder (S: the image's samples per pixel), N one past the
// largest N of the scene's screenshots there (with any sample count), from 1.
std::filesystem::path nextScreenshotPath(const std::filesystem::path& folder,
                                         const std::string& stem, std::uint32_t samples);
