// Where no mistake of the catalogue explains a region, what one of its pixels says instead:
// the reference's ray tree there, term by term (the ambient, each light's diffuse and
// specular, the reflection; or the background), each beside the value the image's colour
// implies for it, were it the only term that differs. A student reads which term their
// tracer gets wrong: a light implied lit where the reference has it blocked, an ambient
// implied three times over.
#pragma once

#include "compare/global_settings.h"
#include "compare/pixel_match.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

struct ImpliedTerm {
    std::string name;     // "ambient", "light 1 (line 3) diffuse, lit", "reflection", ...
    glm::dvec3 reference; // the term's colour in the reference
    glm::dvec3 weight;    // the share of it that reaches the pixel
    glm::dvec3 implied;   // reference + (image - reference) / weight; the reference where
                          // the weight is 0 (the term cannot show there)
};

struct RayTreeReading {
    glm::ivec2 pixel{0};       // in the image
    glm::dvec3 image{0.0};     // the image's colour there, read back through its settings
    glm::dvec3 reference{0.0}; // the reference's, as the image would show it
    std::string meets;         // what the eye ray meets: "the sphere of line 12", ...
    std::vector<ImpliedTerm> terms;
};

// The reading of region's representative pixel (the one whose difference is nearest the
// region's mean) of match, under settings; levels: the image.
RayTreeReading readRayTree(const Scene& scene, const PixelMatch& match, const ImageF& levels,
                           const GlobalSettings& settings, std::size_t region);

// The reading of any pixel of the image (its coordinates in the image).
RayTreeReading readRayTreeAt(const Scene& scene, const ImageF& levels,
                             const GlobalSettings& settings, glm::ivec2 pixel);
