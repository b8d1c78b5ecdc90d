#include "compare/diagnosis.h"

#include "compare/region_facts.h"

#include "reference/reference_renderer.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr long kDiagnosedPerRegion = 2000; // a larger region is sampled evenly

// Whether the image's pixel shows colour (a reference colour, unclamped) as an image under
// settings would, within closeness.
bool shows(const float* pixel, const glm::dvec3& colour, const GlobalSettings& settings,
           double closeness) {
    for (std::size_t k = 0; k < 3; ++k)
        if (std::abs(presentedLevel(settings, colour[settings.channels[k]]) - pixel[k]) > closeness)
            return false;
    return true;
}

} // namespace

std::vector<RegionDiagnosis> diagnoseRegions(const Scene& scene, const PixelMatch& match,
                                             const ImageF& image, const GlobalSettings& settings,
                                             double closeness, std::size_t count, int threads) {
    const std::size_t regions = std::min(count, match.regions.size());
    std::vector<RegionDiagnosis> diagnoses(regions);
    if (regions == 0) return diagnoses;
    const RegionSample sample = sampleRegions(match, settings.flip, count, kDiagnosedPerRegion);
    ReferenceSettings reference = referenceSettingsFor(settings, match.width, match.height);
    // Each region's share of pixels that match with these colours.
    auto shares = [&](const std::vector<glm::dvec3>& colours) {
        std::vector<long> matching(regions, 0);
        for (std::size_t k = 0; k < colours.size(); ++k)
            matching[std::size_t(sample.region[k])] +=
                shows(&image.rgb[sample.at[k] * 3], colours[k], settings, closeness);
        return matching;
    };
    const std::vector<long> plain =
        shares(studentColours(scene, reference, Mistake::None, sample.reference, threads));
    for (int r : sample.region)
        ++diagnoses[std::size_t(r)].traced;
    for (RegionDiagnosis& d : diagnoses)
        d.closeness = closeness;
    for (std::size_t r = 0; r < regions; ++r)
        diagnoses[r].referenceShare = double(plain[r]) / double(std::max(diagnoses[r].traced, 1L));
    for (const MistakeDescription& mistake : mistakeCatalogue()) {
        const std::vector<long> matching =
            shares(studentColours(scene, reference, mistake.mistake, sample.reference, threads));
        for (std::size_t r = 0; r < regions; ++r)
            diagnoses[r].trials.push_back(
                {&mistake, double(matching[r]) / double(std::max(diagnoses[r].traced, 1L))});
    }
    for (RegionDiagnosis& d : diagnoses) {
        std::stable_sort(
            d.trials.begin(), d.trials.end(),
            [](const MistakeTrial& a, const MistakeTrial& b) { return a.share > b.share; });
        if (!d.trials.empty() && d.trials.front().share >= kExplainingShare &&
            d.trials.front().share >= d.referenceShare + 0.4)
            d.cause = d.trials.front();
    }
    return diagnoses;
}
