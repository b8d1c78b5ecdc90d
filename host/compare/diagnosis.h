// Which classic mistake explains a region: the region's pixels are traced by the model of
// another tracer (student_model.h) once per mistake of its catalogue, shown as the image
// shows colours (its global settings), and held to the image's pixels there. A mistake
// explains the region when most of its pixels match with it, where none matched the
// reference; when no mistake does, the region is "not explained by any known mistake",
// never given a wrong cause.
#pragma once

#include "compare/global_settings.h"
#include "compare/pixel_match.h"
#include "compare/student_model.h"
#include "scene/scene.h"

#include <optional>
#include <vector>

// The share of a region's traced pixels that must match with a mistake for it to explain
// the region.
inline constexpr double kExplainingShare = 0.6;

struct MistakeTrial {
    const MistakeDescription* mistake = nullptr;
    double share = 0; // of the traced pixels, those that match with the mistake
};

struct RegionDiagnosis {
    long traced = 0;                  // the region's pixels traced (all, or an even sample)
    double closeness = 0;             // the levels a channel may be off and match, here
    double referenceShare = 0;        // those that match the reference's colour directly
    std::vector<MistakeTrial> trials; // every mistake, the best first
    // The cause: the best trial when it explains the region, else none.
    std::optional<MistakeTrial> cause;
};

// The diagnoses of match's first `count` regions. image: the image's levels; closeness: how
// near a channel must be to count as matching (the tolerance for an exact file).
std::vector<RegionDiagnosis> diagnoseRegions(const Scene& scene, const PixelMatch& match,
                                             const ImageF& image, const GlobalSettings& settings,
                                             double closeness, std::size_t count, int threads = 0);
