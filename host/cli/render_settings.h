// The command line's Options turned into the renderer's RenderSettings, and the headless
// device they ask for, in one place for the headless paths and the window (which then sets
// what it does differently). Kept
// apart from renderer.h so that the renderer does not depend on the command line.
#pragma once

#include "cli/options.h"
#include "render/renderer.h"

// The settings as the command line gives them, the shader and pipeline cache folder
// included (none with --no-cache). Not progressive: one frame of samplesPerPixel.
RenderSettings renderSettingsFrom(const Options& options);

// The device of a headless render (one image or a batch): an instance, with the validation
// layer for --validate, the device --device names (with fp64 when --precision fp64 asks
// for it), and the image size checked against what it can hold.
void openHeadlessDevice(Context& context, const Options& options);
