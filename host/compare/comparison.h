// One handed-in image against the reference of its scene: the global search, then every
// pixel against the reference under the settings found. The reports (compare_report.h)
// say what came of it.
#pragma once

#include "compare/diagnosis.h"
#include "compare/global_search.h"
#include "compare/handed_in_image.h"
#include "compare/implied_terms.h"
#include "compare/pixel_match.h"
#include "compare/region_facts.h"
#include "compare/tolerance.h"
#include "scene/scene.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>

enum class Verdict {
    Matches,                   // as given: no global difference, and within tolerance
    MatchesWithGlobalSettings, // within tolerance once the global differences are applied
    Differs
};
const char* verdictName(Verdict verdict); // "matches", "matches-with-global-differences", "differs"

// The regions the reports describe in full (the JSON lists this many; the text fewer).
inline constexpr std::size_t kListedRegions = 100;
// The regions whose cause is looked for among the classic mistakes (the text lists them).
inline constexpr std::size_t kDiagnosedRegions = 5;

// The share of pixels that must match for "matches".
inline constexpr double kMatchingFraction = 0.995;

// The share of all pixels that the global differences found must make match, over the
// image as given, to be reported: 1% of all pixels and a tenth of those that do not match
// as given. Less, and they explain nothing: an image of another scene, or one whose
// mistakes are its own, can always be nudged a little.
inline double leastGain(double asGivenFraction) {
    return std::max(0.01, 0.1 * (1.0 - asGivenFraction));
}

struct Comparison {
    std::filesystem::path imagePath, scenePath;
    HandedInImage image;
    Tolerance tolerance;
    SearchResult search;
    // The global settings the comparison holds the image to: the search's, or the settings
    // as given when the search's gain too little (then unconvincing names them and
    // unconvincingFraction says what share they reached).
    GlobalSettings settings;
    std::string unconvincing;
    double unconvincingFraction = 0;
    // When a mistake of the catalogue, under the settings as given, explains the search's
    // sample at least as well as the settings it found: that mistake (its share of sample
    // pixels brought close), and the settings found, set aside for it as for unconvincing.
    std::optional<MistakeTrial> mistakeOverSettings;
    std::string setAside;
    double asGivenFraction = 0; // the share of pixels matching as given
    // The reference under the settings found, as the image should hold it: its
    // orientation, channel order and levels.
    ImageF expected;
    PixelMatch match;
    // What the first regions of match (as many as the JSON lists) lie on.
    std::vector<RegionFacts> regionFacts;
    // Which classic mistake explains each of the first regions (as many as the text lists).
    std::vector<RegionDiagnosis> diagnoses;
    // For each of those that no mistake explains (and that is not noise), its
    // representative pixel's ray tree with the terms the image implies; else none.
    std::vector<std::optional<RayTreeReading>> readings;
    Verdict verdict = Verdict::Differs;
    double renderSeconds = 0;    // the full-size reference
    double diagnosisSeconds = 0; // what the regions lie on, and their causes
    double seconds = 0;          // everything, reading the image included
};

struct CompareRequest {
    FixedSettings fixed;
    std::optional<double> tolerance; // overrides the one the image's format gets
    int threads = 0;
};

// The image in its levels, under settings: reference colours (unclamped) to levels, in
// the image's orientation and channel order.
ImageF presentedImage(const ImageF& reference, const GlobalSettings& settings);

Comparison compareWithReference(const std::filesystem::path& imagePath, HandedInImage image,
                                const std::filesystem::path& scenePath, const Scene& scene,
                                const CompareRequest& request);
