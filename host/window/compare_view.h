// The window with --compare FILE: the render (the kernel's trace, which is the reference's
// image), the image handed in and their difference, shown one at a time (keys 1, 2 and 3;
// F flips between the render and the image), and, for I and I + click, the diagnosis of a
// pixel as Raytracer compare reports it (docs/compare.md).
#pragma once

#include "window/viewer.h"

#include <glm/glm.hpp>

// Makes the pictures of viewer.compare.comparison and the image they are shown from.
void openCompareView(Viewer& viewer);
// Needs the device idle; harmless when there is no comparison.
void destroyCompareView(Viewer& viewer);

// Shows picture from the next frame on, and says so on stderr.
void showCompared(Viewer& viewer, ComparedPicture picture);

// The image to show in place of the render, or nullptr to show the render; and its bytes,
// for P's screenshot.
const Image* comparedPicture(const Viewer& viewer);
const Image8* comparedBytes(const Viewer& viewer);

// Prints the diagnosis of pixel (image coordinates) on stdout: the image's and the
// reference's colours there, whether it matches, its region (with what the region lies on
// and its cause) and the terms the image implies at the pixel.
void printPixelDiagnosis(const Viewer& viewer, glm::uvec2 pixel);
