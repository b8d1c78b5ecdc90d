// The command line written back: the inverse of parseOptions (options.h), so that one
// module both reads and writes every option. The window prints it after a screenshot.
#pragma once

#include "cli/options.h"
#include "scene/camera.h"

#include <cstdint>
#include <string>

// word as one shell word: unchanged when it holds only characters no POSIX shell treats
// specially, else in single quotes (a quote inside becomes '\'').
std::string shellQuoted(const std::string& word);

// "Raytracer SCENE ..." that parseOptions reads back into options: --width, --height,
// --depth and --fov always, every other option only when it is not the default (the
// camera in full when its target was given), paths quoted for a shell, numbers exact.
std::string commandLine(const Options& options);

// The headless command that renders the window's image: width x height, spp samples, seen
// from camera, written to OUT.png, with everything else of options that changes pixels
// (depth, fov, background, the kernel choices, --shader-dir).
std::string headlessCommand(const Options& options, const CameraPose& camera, int width, int height,
                            std::uint32_t spp);
