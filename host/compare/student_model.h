// A model of another ray tracer: the reference's geometry (reference_geometry.h) with
// shading of its own that can make one of the classic mistakes of the assignment. With no
// mistake it computes what the reference computes, to the bit; with one, what a tracer
// with that mistake would show. The reference's own shading is never touched, and neither
// is the product's kernel. (The diagnosis of an image's regions is to render them here,
// mistake by mistake, and see which one matches.)
#pragma once

#include "reference/reference_renderer.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

enum class Mistake {
    None,
    NoShadows,                // shadow rays are never cast
    ShadowIgnoresDistance,    // a surface beyond the light still casts its shadow
    SpecularInShadow,         // in shadow, the highlight is still added
    BlinnPhong,               // (N.H)^n instead of (R.V)^n
    UnclampedNDotL,           // lights behind the surface darken it
    AmbientPerLight,          // the ambient term added once per light
    FlatNormals,              // a triangle's geometric normal, not its interpolated one
    MaterialsNotInterpolated, // a triangle's first corner's material everywhere on it
    UnclampedRDotV,           // (R.V)^n taken when R.V < 0 too
    NormalsNotNormalised,     // the interpolated normal used at its interpolated length
    ShadowAcne,               // shadow rays start on the surface and may hit it again
    ReflectionAdded,          // local + ks * reflected, not (1 - ks) * local + ks * reflected
    ColourClampedPerBounce,   // each bounce's local colour clamped to [0, 1] before the blend
    BackFacesCulled,          // triangles seen against their winding are missed, by every ray
    SphereFarRoot,            // a sphere met at its far root, shaded with its outward normal
    WrongAspectRatio,         // the horizontal angle taken equal to the vertical one
    ColourNotClamped          // a colour over 1 written as a byte without a clamp: it wraps
};

struct MistakeDescription {
    Mistake mistake;
    const char* name;  // for options and JSON: "no-shadows"
    const char* words; // for people: "no shadows: shadow rays are never cast"
};

// Every mistake the model can make, Mistake::None excluded, in a fixed order.
const std::vector<MistakeDescription>& mistakeCatalogue();

// The unclamped colour of sample 0 of each pixel (i, j) of pixels, as a tracer that makes
// mistake computes it, with settings' camera, depth and background (settings.spp must be
// 1). Throws std::invalid_argument as renderReference does for settings it refuses.
std::vector<glm::dvec3> studentColours(const Scene& scene, const ReferenceSettings& settings,
                                       Mistake mistake, const std::vector<glm::ivec2>& pixels,
                                       int threads = 0);
