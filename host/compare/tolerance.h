// How far a handed-in image's channels may be from the reference's and still match: an
// exact file is held to 2/255 (a float tracer's last-bit differences); a JPEG file gets
// what its quality makes of an exact image (docs/compare.md has the measurements).
#pragma once

#include "compare/handed_in_image.h"

#include <string>

struct Tolerance {
    double levels = 2;
    std::string reason; // "exact PNG", "JPEG quality 75, estimated from its tables"
};

Tolerance toleranceFor(const HandedInImage& image);
