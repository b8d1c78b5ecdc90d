// What the regions of an image that do not match lie on: the objects their pixels' eye rays
// hit in the reference (by the scene file's lines), and how many of those pixels are in
// shadow, on a mirror or on the background. The first step from where an image differs
// towards why.
#pragma once

#include "compare/global_settings.h"
#include "compare/pixel_match.h"
#include "reference/reference_story.h"
#include "scene/scene.h"

#include <vector>

struct RegionObject {
    StoryPrimitive primitive;
    long pixels = 0;
};

struct RegionFacts {
    long traced = 0; // the region's pixels whose eye rays were traced (all, or a sample)
    std::vector<RegionObject> objects; // the most pixels first
    long background = 0, inShadow = 0, onMirror = 0;
};

// Pixels of match's first `count` regions: every pixel of a region, or an even sample of
// perRegion of a larger one, in image order.
struct RegionSample {
    std::vector<std::size_t> at;       // the pixel's index in the image
    std::vector<glm::ivec2> reference; // the same pixel in the reference's frame (under flip)
    std::vector<int> region;           // its region
};
RegionSample sampleRegions(const PixelMatch& match, Flip flip, std::size_t count, long perRegion);

// The facts of match's first `count` regions (at most), under settings (the image's
// orientation maps its pixels to the reference's). A region of more than
// kTracedPerRegion pixels is sampled evenly.
inline constexpr long kTracedPerRegion = 4000;
std::vector<RegionFacts> regionFacts(const Scene& scene, const PixelMatch& match,
                                     const GlobalSettings& settings, std::size_t count,
                                     int threads = 0);
