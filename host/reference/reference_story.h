// The pixel story of the CPU reference (docs/pixel_story.md): the same ray tree that
// Raytracer --pixel prints for the GPU, recorded by the reference as it traces
// (referencePixelStory, reference_renderer.cpp) and written as the same JSON fields, in
// double precision, so tools/pixel_story can put the two side by side.
#pragma once

#include "reference/reference_renderer.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

// A primitive as the story names it: kind "none", "sphere" or "triangle", its index among
// the file's objects of that kind and its keyword's line.
struct StoryPrimitive {
    const char* kind = "none";
    int index = -1;
    std::int64_t line = 0;
};

struct StoryLightRecord {
    const char* result = "behind"; // "lit", "blocked", or "behind" (N.L <= 0 or at the point)
    StoryPrimitive blocker;        // blocked: the nearest surface on the shadow ray
    double nDotL = 0;
    glm::dvec3 contribution{0.0}; // Lc (kd N.L + ks max(R.V, 0)^shininess) when lit
};

struct StoryBounceRecord {
    glm::dvec3 origin{0.0}, direction{0.0};
    StoryPrimitive hit;
    double t = 0;
    glm::dvec3 barycentric{0.0};
    glm::dvec3 normal{0.0};
    Material material;
    glm::dvec3 mirrorWeight{0.0}; // ks times the mirror share (SurfacePoint)
    std::vector<StoryLightRecord> lights;
    glm::dvec3 local{0.0}; // the local Phong colour; a miss: the background
    glm::dvec3 throughput{1.0}, color{0.0};
    const char* next = "miss"; // "reflect", "miss", "no-mirror" or "depth"
};

struct ReferenceStory {
    glm::dvec2 sampleOffset{0.5};
    std::vector<StoryBounceRecord> bounces;
    glm::dvec3 sampleColor{0.0}; // sample 0, before the clamp
    glm::dvec3 pixelColor{0.0};  // the average of the clamped samples
};

// Sample 0's ray tree of pixel (i, j) and the pixel's value (tracePixel's).
ReferenceStory referencePixelStory(const Scene& scene, const ReferenceSettings& settings, int i,
                                   int j);

// What the eye ray of a pixel meets, in short: for telling what a region of an image lies on
// (compare's regions) without a whole story per pixel.
struct EyeRayFacts {
    StoryPrimitive hit;    // kind "none": the ray meets only the background
    bool inShadow = false; // a light faces the point and something blocks it
    bool onMirror = false; // the point reflects (ks > 0) and the depth allows a bounce
};

// The facts of sample 0's eye ray of each pixel (i, j) of pixels. Throws as
// renderReference does for settings it refuses.
std::vector<EyeRayFacts> referenceEyeRays(const Scene& scene, const ReferenceSettings& settings,
                                          const std::vector<glm::ivec2>& pixels, int threads = 0);

// The story as one JSON object with Raytracer --pixel's fields ("renderer": "reference").
std::string referenceStoryJson(const ReferenceStory& story, const Scene& scene,
                               const ReferenceSettings& settings, const std::string& scenePath,
                               int i, int j);
