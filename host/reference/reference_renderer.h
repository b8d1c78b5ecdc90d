// The independent CPU reference: the model of docs/model.md in double precision, with its own
// intersection methods (see reference_renderer.cpp). Slow and simple on purpose;
// the tests compare the GPU renderer against it.
#pragma once

#include "base/float_image.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

struct ReferenceSettings {
    int width = 640, height = 480;
    int depth = 5; // reflection bounces after the primary hit
    int spp = 1;   // 1: pixel centre; n*n: regular grid; else the most square grid of n
    double fovDegrees = 60;
    // The eye and where it looks; the defaults are the default camera (origin, down -z).
    glm::dvec3 cameraPosition{0.0};
    glm::dvec3 cameraTarget{0.0, 0.0, -1.0};
    glm::dvec3 cameraUp{0.0, 1.0, 0.0};
    glm::dvec3 background{1.0};
    // floor(c*255) instead of rounding, to compare with the course's images.
    bool truncate = false;
    // Rays through the pixels' top-left corners (i, j) instead of their centres, as some
    // tracers do: every sample position moves by half a pixel up and left.
    bool cornerRays = false;
    // false: renderReferenceFloat averages the samples' colours as traced, above 1 or
    // below 0, for a caller that applies its own scale before clamping.
    bool clampSamples = true;
    // Shadow rays leave smooth-shaded triangles from Hanika's shifted point (--terminator;
    // reference_render turns it on for an OBJ model unless told otherwise, as Raytracer does).
    bool terminatorFix = false;
};

// Renders the whole image. threads = 0 uses the host's policy (workerThreads(), base/parallel.h).
// Throws std::invalid_argument for a non-positive size or spp, a negative depth or
// a field of view outside (0, 180) degrees, or a camera whose target is its position or
// whose up is parallel to the view.
Image8 renderReference(const Scene& scene, const ReferenceSettings& settings, int threads = 0);

// The same image before quantisation: each pixel's average of clamped samples, computed in
// double and stored as float (for -o out.pfm|out.exr). settings.truncate plays no part.
ImageF renderReferenceFloat(const Scene& scene, const ReferenceSettings& settings, int threads = 0);

// One pixel (column i from the left, row j from the top) as it goes into the
// image: the average of its clamped samples, in [0,1], before quantisation.
glm::dvec3 tracePixel(const Scene& scene, const ReferenceSettings& settings, int i, int j);

// The unclamped colour of one ray from the eye (origin 0) in direction dir, with
// settings.depth bounces: for debugging single rays by hand.
glm::dvec3 traceEyeRay(const Scene& scene, const ReferenceSettings& settings, glm::dvec3 dir);

// What one eye ray leaves open to the two settings a single trace can serve: the
// reflection depth and the background colour. With depth d (0 to the depth traced), the
// ray's unclamped colour is own[d] + throughBackground[d] * background, per channel: the
// path as far as bounce d, folded as the model's recursion folds it, with the share of
// the colour that reaches the background kept apart (zero when the path ends on a surface).
struct RayTerms {
    std::vector<glm::dvec3> own, throughBackground; // index: depth
};

// The terms of the first sample of each pixel (i, j) of pixels, for depths 0 to
// settings.depth (settings.background plays no part). Throws std::invalid_argument for
// settings renderReference refuses, or spp other than 1 (the average of clamped
// samples is not linear in the background).
std::vector<RayTerms> referenceTerms(const Scene& scene, const ReferenceSettings& settings,
                                     const std::vector<glm::ivec2>& pixels, int threads = 0);

// The byte written for a channel value: clamp to [0,1], then floor(c*255+0.5), or
// floor(c*255) when truncating. NaN becomes 0.
int quantizeChannel(double c, bool truncate);
