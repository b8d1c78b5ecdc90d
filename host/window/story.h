// The I key: the pixel story (docs/pixel_story.md) of the pixel under the mouse, or of the
// pixel clicked with I held.
#pragma once

#include "window/viewer.h"

// Traces the pixel the request names (Viewer::storyX, storyY: under the cursor when I was
// pressed, or the click's) with the recording kernel and prints its story as JSON on stdout,
// at the window's sample target (what the window shows once refinement is done); a line on
// stderr says which pixel ("pixel X,Y", or "clicked pixel X,Y"), or that the mouse is not
// over the image. The loop calls it after its frame, when the output image holds a trace.
void printStoryUnderCursor(Viewer& viewer);
