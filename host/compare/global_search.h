// The global search: the settings (global_settings.h) under which the reference best
// matches an image, found cheaply. Every pixel of a sample grid (about 20000 pixels) is
// traced once per camera variant (field-of-view axis and ray position: at most four), and
// one trace serves every depth and background (RayTerms); the orientation, gamma,
// quantisation, channel order and brightness are applied to those traces.
#pragma once

#include "base/float_image.h"
#include "compare/global_settings.h"
#include "scene/scene.h"

#include <vector>

// Which settings the user fixed (the compare options); the others are searched. The
// values of fixed ones are taken from values.
struct FixedSettings {
    GlobalSettings values;
    bool depth = false, background = false, fovAxis = false, rays = false, flip = false,
         gamma = false, channels = false, brightness = false, quantize = false;
};

struct SearchResult {
    // The best: among the settings whose share of close sample pixels is near the highest
    // (within 0.2%, and 5% of what the highest lacks), the one with the fewest departures from the
    // defaults (then the highest share, then the lowest mean error).
    GlobalSettings settings;
    double close = 0;     // its share of sample pixels with every channel close
    double meanError = 0; // its mean absolute channel difference on the sample, levels
    long candidates = 0;  // settings tried
    long samplePixels = 0;
    long tracedRays = 0; // eye rays traced, over all camera variants
    double seconds = 0;
};

// levels: the image in channel levels 0..255 (handed_in_image.h), at the size to trace.
// closeness: how many levels apart a channel may be and still count as the same in the
// search (half a level for an exact file: only the same byte). threads as
// renderReference's.
SearchResult searchGlobalSettings(const Scene& scene, const ImageF& levels,
                                  const FixedSettings& fixed, double closeness, int threads = 0);

// The pixels the search samples in an image of this size: an even grid of about 20000.
std::vector<glm::ivec2> searchSamplePixels(int width, int height);

// The settings as given: the defaults, with what the user fixed.
GlobalSettings givenSettings(const FixedSettings& fixed);
