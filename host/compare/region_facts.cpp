#include "compare/region_facts.h"

#include <algorithm>
#include <string>

RegionSample sampleRegions(const PixelMatch& match, Flip flip, std::size_t count, long perRegion) {
    const std::size_t regions = std::min(count, match.regions.size());
    std::vector<long> step(regions), seen(regions, 0);
    for (std::size_t r = 0; r < regions; ++r)
        step[r] = (match.regions[r].pixels + perRegion - 1) / perRegion;
    RegionSample sample;
    for (std::size_t p = 0; p < match.regionOf.size(); ++p) {
        const int r = match.regionOf[p];
        if (r < 0 || std::size_t(r) >= regions) continue;
        if (seen[std::size_t(r)]++ % step[std::size_t(r)] != 0) continue;
        const int x = int(p % std::size_t(match.width)), y = int(p / std::size_t(match.width));
        sample.at.push_back(p);
        sample.reference.push_back(referencePixel(flip, x, y, match.width, match.height));
        sample.region.push_back(r);
    }
    return sample;
}

std::vector<RegionFacts> regionFacts(const Scene& scene, const PixelMatch& match,
                                     const GlobalSettings& settings, std::size_t count,
                                     int threads) {
    const std::size_t regions = std::min(count, match.regions.size());
    const RegionSample sample = sampleRegions(match, settings.flip, count, kTracedPerRegion);
    const std::vector<EyeRayFacts> rays =
        referenceEyeRays(scene, referenceSettingsFor(settings, match.width, match.height),
                         sample.reference, threads);
    std::vector<RegionFacts> facts(regions);
    for (std::size_t k = 0; k < rays.size(); ++k) {
        RegionFacts& f = facts[std::size_t(sample.region[k])];
        const EyeRayFacts& ray = rays[k];
        ++f.traced;
        if (std::string(ray.hit.kind) == "none") {
            ++f.background;
            continue;
        }
        f.inShadow += ray.inShadow;
        f.onMirror += ray.onMirror;
        auto same = [&](const RegionObject& o) {
            return o.primitive.line == ray.hit.line && o.primitive.index == ray.hit.index &&
                   std::string(o.primitive.kind) == ray.hit.kind;
        };
        auto found = std::find_if(f.objects.begin(), f.objects.end(), same);
        if (found == f.objects.end())
            f.objects.push_back({ray.hit, 1});
        else
            ++found->pixels;
    }
    for (RegionFacts& f : facts)
        std::stable_sort(
            f.objects.begin(), f.objects.end(),
            [](const RegionObject& a, const RegionObject& b) { return a.pixels > b.pixels; });
    return facts;
}
