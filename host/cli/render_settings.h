// The command line's Options turned into the renderer's RenderSettings, in one place for
// the headless path and the window (which then sets what it does differently). Kept
// apart from renderer.h so that the renderer does not depend on the command line.
#pragma once

#include "cli/options.h"
#include "render/renderer.h"

// The settings as the command line gives them, the shader and pipeline cache folder
// included (none with --no-cache). Not progressive: one frame of samplesPerPixel.
RenderSettings renderSettingsFrom(const Options& options);
