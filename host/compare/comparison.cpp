#include "compare/comparison.h"

#include "compare/jpeg_codec.h"
#include "reference/reference_renderer.h"

#include <chrono>

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The reference's colours (unclamped: brightness comes before the clamp) for an image like
// like under settings.
ImageF referenceColours(const Scene& scene, const GlobalSettings& settings, const ImageF& like,
                        int threads) {
    ReferenceSettings reference = referenceSettingsFor(settings, like.width, like.height);
    reference.clampSamples = false;
    return renderReferenceFloat(scene, reference, threads);
}

// Whether two settings trace the same reference: the rest only changes how its colours
// are presented.
bool sameTrace(const GlobalSettings& a, const GlobalSettings& b) {
    return a.depth == b.depth && a.background == b.background && a.fovDegrees == b.fovDegrees &&
           a.fovAxis == b.fovAxis && a.rays == b.rays;
}

// Whether found departs from given where a classic mistake can pass for a global
// difference: reflections added look like a brighter image with another background, or
// like a gamma curve; ambient per light, like a brighter image; a wrong aspect ratio, like
// the angle across the width. Only an orientation, a channel order and the rays' place in
// the pixel are never a mistake of the catalogue in disguise, and their check would cost a
// trace per mistake.
bool mayBeAMistake(const GlobalSettings& found, const GlobalSettings& given) {
    GlobalSettings plain = found;
    plain.flip = given.flip;
    plain.channels = given.channels;
    plain.rays = given.rays;
    return departures(plain) > departures(given);
}

// The image against expected. A JPEG is held against the reference written as it was
// (jpeg_codec.h), so that both carry compression errors of the same kind.
PixelMatch matchWith(const Comparison& comparison, const ImageF& expected) {
    const ImageF& levels = comparison.image.levels;
    if (comparison.image.jpegFile.empty())
        return matchPixels(levels, expected, comparison.tolerance.levels);
    return matchPixels(levels, throughJpegLike(expected, comparison.image.jpegFile),
                       comparison.tolerance.levels);
}

} // namespace

const char* verdictName(Verdict verdict) {
    switch (verdict) {
    case Verdict::Matches:
        return "matches";
    case Verdict::MatchesWithGlobalSettings:
        return "matches-with-global-differences";
    case Verdict::Differs:
        return "differs";
    }
    return "differs";
}

ImageF presentedImage(const ImageF& reference, const GlobalSettings& settings) {
    ImageF image;
    image.width = reference.width;
    image.height = reference.height;
    image.rgb.resize(reference.rgb.size());
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::ivec2 source =
                referencePixel(settings.flip, x, y, image.width, image.height);
            const float* from =
                &reference.rgb[(std::size_t(source.y) * std::size_t(image.width) + source.x) * 3];
            float* to = &image.rgb[(std::size_t(y) * std::size_t(image.width) + x) * 3];
            for (std::size_t k = 0; k < 3; ++k)
                to[k] = float(presentedLevel(settings, from[settings.channels[k]]));
        }
    return image;
}

Comparison compareWithReference(const std::filesystem::path& imagePath, HandedInImage image,
                                const std::filesystem::path& scenePath, const Scene& scene,
                                const CompareRequest& request) {
    const auto start = std::chrono::steady_clock::now();
    Comparison comparison;
    comparison.imagePath = imagePath;
    comparison.scenePath = scenePath;
    comparison.image = std::move(image);
    comparison.tolerance = toleranceFor(comparison.image);
    if (request.tolerance) {
        comparison.tolerance.levels = *request.tolerance;
        comparison.tolerance.reason = "given with --tolerance";
    }
    const ImageF& levels = comparison.image.levels;
    // The search tells settings apart by the share of pixels they get exactly right (an
    // exact file) or within twice the tolerance (a JPEG, whose noise the reference does not
    // carry in the search).
    const double closeness =
        isExactFormat(comparison.image.format) ? 0.5 : 2 * comparison.tolerance.levels;
    comparison.search =
        searchGlobalSettings(scene, levels, request.fixed, closeness, request.threads);
    comparison.settings = comparison.search.settings;
    const GlobalSettings given = givenSettings(request.fixed);
    if (mayBeAMistake(comparison.settings, given)) {
        const auto checkStart = std::chrono::steady_clock::now();
        const MistakeTrial mistake =
            bestMistakeOnSample(scene, levels, given, closeness, request.threads);
        if (mistake.mistake && mistake.share >= comparison.search.close) {
            comparison.mistakeOverSettings = mistake;
            comparison.setAside = departureOptions(comparison.settings);
            comparison.settings = given;
        }
        comparison.search.seconds += secondsSince(checkStart); // part of choosing settings
    }
    const auto renderStart = std::chrono::steady_clock::now();
    const ImageF colours = referenceColours(scene, comparison.settings, levels, request.threads);
    ImageF expected = presentedImage(colours, comparison.settings);
    comparison.match = matchWith(comparison, expected);
    if (departures(comparison.settings) > departures(given)) {
        // As given, on every pixel: the settings found must gain enough over it. A flip, a
        // gamma or the like presents the same trace otherwise.
        ImageF asGiven =
            presentedImage(sameTrace(given, comparison.settings)
                               ? colours
                               : referenceColours(scene, given, levels, request.threads),
                           given);
        PixelMatch asGivenMatch = matchWith(comparison, asGiven);
        comparison.asGivenFraction = asGivenMatch.fractionMatching;
        // Both within tolerance, a difference below it (truncation, say) counts when the
        // settings found halve the mean difference.
        const bool gains =
            comparison.match.fractionMatching >=
                asGivenMatch.fractionMatching + leastGain(asGivenMatch.fractionMatching) ||
            (asGivenMatch.fractionMatching >= kMatchingFraction &&
             comparison.match.meanAbsoluteDifference < 0.5 * asGivenMatch.meanAbsoluteDifference);
        if (!gains) {
            comparison.unconvincing = departureOptions(comparison.settings);
            comparison.unconvincingFraction = comparison.match.fractionMatching;
            comparison.settings = given;
            expected = std::move(asGiven);
            comparison.match = std::move(asGivenMatch);
        }
    } else {
        comparison.asGivenFraction = comparison.match.fractionMatching;
    }
    comparison.expected = std::move(expected);
    comparison.renderSeconds = secondsSince(renderStart);
    const auto diagnosisStart = std::chrono::steady_clock::now();
    comparison.regionFacts =
        regionFacts(scene, comparison.match, comparison.settings, kListedRegions, request.threads);
    comparison.diagnoses = diagnoseRegions(
        scene, comparison.match,
        {levels, comparison.expected, comparison.image.jpegFile, comparison.tolerance.levels},
        comparison.settings, kDiagnosedRegions, request.threads);
    for (std::size_t r = 0; r < comparison.diagnoses.size(); ++r) {
        const RegionDiagnosis& d = comparison.diagnoses[r];
        comparison.readings.push_back(
            d.cause || d.referenceShare >= kExplainingShare
                ? std::nullopt
                : std::optional(
                      readRayTree(scene, comparison.match, levels, comparison.settings, r)));
    }
    comparison.diagnosisSeconds = secondsSince(diagnosisStart);
    const bool within = comparison.match.fractionMatching >= kMatchingFraction;
    comparison.verdict = !within ? Verdict::Differs
                         : departures(comparison.settings) == departures(given)
                             ? Verdict::Matches
                             : Verdict::MatchesWithGlobalSettings;
    comparison.seconds = secondsSince(start);
    return comparison;
}
