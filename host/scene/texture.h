// A model's texture as the renderer samples it: the decoded image and the file it came from.
// How it is sampled (bilinear, wrapping) is docs/models.md's rule, which the kernel
// (shaders/texture.glsl) and the reference (reference_geometry.cpp) each implement.
#pragma once

#include "base/image_io.h"

#include <string>

struct Texture {
    std::string file; // as the model names it, found (model/texture_files.h)
    Image8 image;     // RGBA8, top row first; the sampled colour is rgb / 255
};
