#include "compare/implied_terms.h"

#include "reference/reference_story.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

std::string primitiveWords(const StoryPrimitive& p) {
    if (std::string(p.kind) == "none") return "the background";
    return std::string("the ") + p.kind + " of line " + std::to_string(p.line);
}

// The pixel of region whose signed difference is nearest the region's mean.
glm::ivec2 representativePixel(const PixelMatch& match, std::size_t region) {
    const double mean = match.regions[region].meanSignedDifference;
    double nearest = std::numeric_limits<double>::infinity();
    std::size_t best = 0;
    for (std::size_t p = 0; p < match.regionOf.size(); ++p) {
        if (match.regionOf[p] != int(region)) continue;
        const double off = std::abs(double(match.signedDifference[p]) - mean);
        if (off < nearest) {
            nearest = off;
            best = p;
        }
    }
    return {int(best % std::size_t(match.width)), int(best / std::size_t(match.width))};
}

} // namespace

RayTreeReading readRayTree(const Scene& scene, const PixelMatch& match, const ImageF& levels,
                           const GlobalSettings& settings, std::size_t region) {
    return readRayTreeAt(scene, levels, settings, representativePixel(match, region));
}

RayTreeReading readRayTreeAt(const Scene& scene, const ImageF& levels,
                             const GlobalSettings& settings, glm::ivec2 pixel) {
    RayTreeReading reading;
    reading.pixel = pixel;
    const glm::ivec2 at =
        referencePixel(settings.flip, pixel.x, pixel.y, levels.width, levels.height);
    ReferenceSettings traced = referenceSettingsFor(settings, levels.width, levels.height);
    traced.clampSamples = false;
    const ReferenceStory story = referencePixelStory(scene, traced, at.x, at.y);
    // Both colours as the image holds them: the reference clamped where the image clamps,
    // the image's levels read back; in the reference's channel order.
    const float* shown =
        &levels.rgb[(std::size_t(pixel.y) * std::size_t(levels.width) + std::size_t(pixel.x)) * 3];
    for (std::size_t k = 0; k < 3; ++k) {
        const int c = settings.channels[k];
        reading.image[c] = linearFromLevel(settings, shown[k]);
        reading.reference[c] =
            std::clamp(story.sampleColor[c] * settings.brightness, 0.0, 1.0) / settings.brightness;
    }
    const glm::dvec3 difference = reading.image - reading.reference;
    auto add = [&](std::string name, glm::dvec3 value, glm::dvec3 weight) {
        glm::dvec3 implied = value;
        for (int c = 0; c < 3; ++c)
            if (weight[c] > 0) implied[c] += difference[c] / weight[c];
        reading.terms.push_back({std::move(name), value, weight, implied});
    };
    if (story.bounces.empty()) return reading;
    const StoryBounceRecord& eye = story.bounces.front();
    reading.meets = primitiveWords(eye.hit);
    if (std::string(eye.hit.kind) == "none") {
        add("background", eye.local, glm::dvec3(1.0));
        return reading;
    }
    const bool reflects = std::string(eye.next) == "reflect";
    const glm::dvec3 ks = eye.mirrorWeight;
    const glm::dvec3 localWeight = reflects ? 1.0 - ks : glm::dvec3(1.0);
    add("ambient", scene.ambient, localWeight);
    for (std::size_t l = 0; l < eye.lights.size() && l < scene.lights.size(); ++l) {
        const StoryLightRecord& light = eye.lights[l];
        const std::string name = "light " + std::to_string(l + 1) + " (line " +
                                 std::to_string(scene.lights[l].line) + ") ";
        const glm::dvec3 diffuse = std::string(light.result) == "lit"
                                       ? scene.lights[l].color * eye.material.diffuse * light.nDotL
                                       : glm::dvec3(0.0);
        add(name + "diffuse, " + light.result, diffuse, localWeight);
        add(name + "specular, " + light.result, light.contribution - diffuse, localWeight);
    }
    if (reflects) {
        // What the mirror shows: the rest of the colour, divided by its weight.
        glm::dvec3 reflected(0.0);
        for (int c = 0; c < 3; ++c)
            if (ks[c] > 0)
                reflected[c] = (story.sampleColor[c] - localWeight[c] * eye.local[c]) / ks[c];
        add("reflection (" +
                primitiveWords(story.bounces.size() > 1 ? story.bounces[1].hit : StoryPrimitive{}) +
                ")",
            reflected, ks);
    }
    return reading;
}
