// The window's P key: the output image as it stands, read back and written as a PNG
// under a name that does not overwrite an earlier one.
#pragma once

#include "base/image_io.h"
#include "render/renderer.h"

#include <filesystem>
#include <string>

// Copies the output image (in TRANSFER_SRC_OPTIMAL after a trace) to host memory.
// Waits for the device to be idle first.
Image8 readOutputImage(const Context& context, const Renderer& renderer);

// STEM-screenshot-N.png in folder for the smallest N >= 1 not taken yet.
std::filesystem::path nextScreenshotPath(const std::filesystem::path& folder,
                                         const std::string& stem);
