#include "compare/diagnosis.h"

#include "compare/global_search.h"
#include "compare/jpeg_codec.h"
#include "compare/region_facts.h"

#include "reference/reference_renderer.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr long kDiagnosedPerRegion = 2000; // a larger region is sampled evenly
// A JPEG's region is judged on whole blocks: at most this many of its blocks, evenly spread
// (about as many pixels as kDiagnosedPerRegion). 16 pixels: a block of luma and of 4:2:0
// chroma alike.
constexpr long kBlocksPerRegion = 8;
constexpr int kBlock = 16;
// Shares of a region this close explain it alike.
constexpr double kTiedShare = 0.02;

// The pixels a diagnosis traces and those it judges.
struct Trial {
    std::vector<std::size_t> traced;   // image indices whose colours are traced
    std::vector<glm::ivec2> reference; // the same pixels in the reference's frame
    std::vector<std::size_t> judged;   // image indices held to the image
    std::vector<int> region;           // each judged pixel's region
};

// An exact file: an even sample of each region, traced and judged alike.
Trial sampledPixels(const PixelMatch& match, Flip flip, std::size_t count) {
    RegionSample sample = sampleRegions(match, flip, count, kDiagnosedPerRegion);
    Trial trial;
    trial.traced = sample.at;
    trial.reference = std::move(sample.reference);
    trial.judged = std::move(sample.at);
    trial.region = std::move(sample.region);
    return trial;
}

// A JPEG: whole blocks, up to kBlocksPerRegion of each region spread evenly over its blocks;
// every pixel of them traced, the regions' pixels in them judged.
Trial blockPixels(const PixelMatch& match, Flip flip, std::size_t count) {
    const std::size_t regions = std::min(count, match.regions.size());
    const int columns = (match.width + kBlock - 1) / kBlock;
    const int rows = (match.height + kBlock - 1) / kBlock;
    auto blockOf = [&](std::size_t p) {
        const int x = int(p % std::size_t(match.width)), y = int(p / std::size_t(match.width));
        return std::size_t(y / kBlock) * std::size_t(columns) + std::size_t(x / kBlock);
    };
    // Each region's blocks, in image order, each once.
    const std::size_t blockCount = std::size_t(columns) * std::size_t(rows);
    std::vector<std::vector<std::size_t>> blocksOf(regions);
    std::vector<std::vector<unsigned char>> listed(regions, std::vector<unsigned char>(blockCount));
    for (std::size_t p = 0; p < match.regionOf.size(); ++p) {
        const int r = match.regionOf[p];
        if (r < 0 || std::size_t(r) >= regions) continue;
        const std::size_t b = blockOf(p);
        if (listed[std::size_t(r)][b]) continue;
        listed[std::size_t(r)][b] = 1;
        blocksOf[std::size_t(r)].push_back(b);
    }
    std::vector<unsigned char> chosen(blockCount, 0);
    for (std::vector<std::size_t>& blocks : blocksOf) {
        std::sort(blocks.begin(), blocks.end());
        const std::size_t step = (blocks.size() + kBlocksPerRegion - 1) / kBlocksPerRegion;
        for (std::size_t k = 0; k < blocks.size(); k += step)
            chosen[blocks[k]] = 1;
    }
    Trial trial;
    for (std::size_t p = 0; p < match.regionOf.size(); ++p) {
        if (!chosen[blockOf(p)]) continue;
        const int x = int(p % std::size_t(match.width)), y = int(p / std::size_t(match.width));
        trial.traced.push_back(p);
        trial.reference.push_back(referencePixel(flip, x, y, match.width, match.height));
        const int r = match.regionOf[p];
        if (r < 0 || std::size_t(r) >= regions) continue;
        trial.judged.push_back(p);
        trial.region.push_back(r);
    }
    return trial;
}

// Whether the image's pixel is within closeness of the levels shown, channel by channel.
bool near(const float* pixel, const float* shown, double closeness) {
    for (std::size_t k = 0; k < 3; ++k)
        if (std::abs(shown[k] - pixel[k]) > closeness) return false;
    return true;
}

} // namespace

MistakeTrial bestMistakeOnSample(const Scene& scene, const ImageF& levels,
                                 const GlobalSettings& settings, double closeness, int threads) {
    // As the search samples: pixels of the reference, each held to the image's pixel that
    // shows it under the orientation.
    const std::vector<glm::ivec2> samples = searchSamplePixels(levels.width, levels.height);
    const ReferenceSettings traced = referenceSettingsFor(settings, levels.width, levels.height);
    MistakeTrial best;
    for (const MistakeDescription& mistake : mistakeCatalogue()) {
        const std::vector<glm::dvec3> colours =
            studentColours(scene, traced, mistake.mistake, samples, threads);
        long close = 0;
        for (std::size_t k = 0; k < samples.size(); ++k) {
            float shown[3];
            for (std::size_t c = 0; c < 3; ++c)
                shown[c] = float(presentedLevel(settings, colours[k][settings.channels[c]]));
            const glm::ivec2 q = referencePixel(settings.flip, samples[k].x, samples[k].y,
                                                levels.width, levels.height);
            const std::size_t at = std::size_t(q.y) * std::size_t(levels.width) + std::size_t(q.x);
            close += near(&levels.rgb[at * 3], shown, closeness);
        }
        const double share = double(close) / double(std::max<std::size_t>(samples.size(), 1));
        if (!best.mistake || share > best.share) best = {&mistake, share};
    }
    return best;
}

std::vector<RegionDiagnosis> diagnoseRegions(const Scene& scene, const PixelMatch& match,
                                             const DiagnosedImage& image,
                                             const GlobalSettings& settings, std::size_t count,
                                             int threads) {
    const std::size_t regions = std::min(count, match.regions.size());
    std::vector<RegionDiagnosis> diagnoses(regions);
    if (regions == 0) return diagnoses;
    const bool jpeg = !image.jpegFile.empty();
    const Trial trial = jpeg ? blockPixels(match, settings.flip, count)
                             : sampledPixels(match, settings.flip, count);
    const ReferenceSettings reference = referenceSettingsFor(settings, match.width, match.height);
    // Each region's count of judged pixels that the image shows as a tracer with mistake
    // would: its colours presented in the image's levels, over the reference's image and
    // through the file's JPEG writing for a JPEG. With a mistake, only pixels it changes
    // (beyond the closeness, from the reference's) count: a mistake that leaves a pixel as
    // it was cannot be why the pixel differs, and near the tolerance (another encoder's
    // JPEG noise) a small change matches by chance.
    ImageF plainShown;
    auto matching = [&](Mistake mistake) {
        const std::vector<glm::dvec3> colours =
            studentColours(scene, reference, mistake, trial.reference, threads);
        ImageF shown = image.expected;
        for (std::size_t k = 0; k < trial.traced.size(); ++k)
            for (std::size_t c = 0; c < 3; ++c)
                shown.rgb[trial.traced[k] * 3 + c] =
                    float(presentedLevel(settings, colours[k][settings.channels[c]]));
        if (jpeg) shown = throughJpegLike(shown, image.jpegFile);
        if (mistake == Mistake::None) plainShown = shown;
        std::vector<long> counts(regions, 0);
        for (std::size_t k = 0; k < trial.judged.size(); ++k) {
            const std::size_t p = trial.judged[k];
            const bool changed = mistake == Mistake::None ||
                                 !near(&plainShown.rgb[p * 3], &shown.rgb[p * 3], image.closeness);
            counts[std::size_t(trial.region[k])] +=
                changed && near(&image.levels.rgb[p * 3], &shown.rgb[p * 3], image.closeness);
        }
        return counts;
    };
    for (int r : trial.region)
        ++diagnoses[std::size_t(r)].traced;
    auto share = [&](long pixels, std::size_t r) {
        return double(pixels) / double(std::max(diagnoses[r].traced, 1L));
    };
    const std::vector<long> plain = matching(Mistake::None);
    for (std::size_t r = 0; r < regions; ++r) {
        diagnoses[r].closeness = image.closeness;
        diagnoses[r].referenceShare = share(plain[r], r);
    }
    // Each mistake's judged pixels that match, over all the regions.
    std::vector<long> everywhere;
    for (const MistakeDescription& mistake : mistakeCatalogue()) {
        const std::vector<long> counts = matching(mistake.mistake);
        everywhere.push_back(0);
        for (std::size_t r = 0; r < regions; ++r) {
            diagnoses[r].trials.push_back({&mistake, share(counts[r], r)});
            everywhere.back() += counts[r];
        }
    }
    auto overall = [&](const MistakeTrial& t) {
        return everywhere[std::size_t(t.mistake - mistakeCatalogue().data())];
    };
    for (RegionDiagnosis& d : diagnoses) {
        std::stable_sort(
            d.trials.begin(), d.trials.end(),
            [](const MistakeTrial& a, const MistakeTrial& b) { return a.share > b.share; });
        // Two mistakes can explain a region alike (a triangle culled from behind casts no
        // shadow, as with no shadows at all): the one that explains more of the other
        // regions too goes first.
        auto tied = std::find_if(d.trials.begin(), d.trials.end(), [&](const MistakeTrial& t) {
            return t.share < d.trials.front().share - kTiedShare;
        });
        std::stable_sort(d.trials.begin(), tied, [&](const MistakeTrial& a, const MistakeTrial& b) {
            return overall(a) > overall(b);
        });
        if (!d.trials.empty() && d.trials.front().share >= kExplainingShare &&
            d.trials.front().share >= d.referenceShare + 0.4 &&
            d.trials.front().share * double(d.traced) >= double(kLeastExplainedPixels) - 1e-9)
            d.cause = d.trials.front();
    }
    return diagnoses;
}
