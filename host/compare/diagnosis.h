// Which classic mistake explains a region: the region's pixels are traced by the model of
// another tracer (student_model.h) once per mistake of its catalogue, shown as the image
// shows colours (its global settings), and held to the image's pixels there. A mistake
// explains the region when most of its pixels match with it, where none matched the
// reference; when no mistake does, the region is "not explained by any known mistake",
// never given a wrong cause.
//
// A JPEG's pixels carry the noise of its compression, which the model's colours do not:
// there whole blocks of a region (as the file's blocks lie) are traced, set into the
// reference's image and written as the file was written (jpeg_codec.h) before they are
// held to the image, so that both carry the same noise.
#pragma once

#include "compare/global_settings.h"
#include "compare/pixel_match.h"
#include "compare/student_model.h"
#include "scene/scene.h"

#include <cstdint>
#include <optional>
#include <vector>

// The share of a region's traced pixels that must match with a mistake for it to explain
// the region, and how many pixels at least: a handful of noise pixels (another encoder's
// JPEG, near the tolerance) can match any mistake that moves them a little.
inline constexpr double kExplainingShare = 0.6;
inline constexpr long kLeastExplainedPixels = 8;

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

// The mistake that best explains the whole image under settings, with the share of the
// global search's sample pixels (global_search.h) whose channels it brings within closeness
// of the image, as the search counts them. A mistake can pass for a global difference
// (reflections added for a brighter image, ambient per light for another background): the
// comparison weighs the two with it.
MistakeTrial bestMistakeOnSample(const Scene& scene, const ImageF& levels,
                                 const GlobalSettings& settings, double closeness, int threads = 0);

// The image a region's pixels are held to, and how.
struct DiagnosedImage {
    const ImageF& levels;   // the image's levels
    const ImageF& expected; // the reference as the image should show it, before any JPEG
    const std::vector<std::uint8_t>& jpegFile; // the file, when it is a JPEG; else empty
    double closeness; // how near a channel must be to count as matching (the tolerance)
};

// The diagnoses of match's first `count` regions, under settings.
std::vector<RegionDiagnosis> diagnoseRegions(const Scene& scene, const PixelMatch& match,
                                             const DiagnosedImage& image,
                                             const GlobalSettings& settings, std::size_t count,
                                             int threads = 0);
