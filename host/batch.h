// Batches (docs/batches.md): several scenes, the frames of --turntable or --camera-path, or
// both, rendered headless one image after another in one process. The Vulkan instance and
// device, the on-disk caches and the compiled kernels (host/render/kernel_cache.h) are made
// once and kept from one image to the next; only what the scene holds is made per scene.
#pragma once

#include "cli/options.h"

// Renders every image of the batch. A scene that does not load is reported as it would be
// alone (FILE:LINE: error: ...) and skipped, and the others still render: a batch of a
// hundred scenes is not lost to one typo, and the exit status still says one failed.
// Returns the number of scenes that did not load. Throws on every other failure (Vulkan,
// output, a camera path that does not parse, Ctrl-C), which ends the batch at once.
int runBatch(const Options& options);
