// For the tests of the model of another tracer (host/compare/student_model.h) and of the
// diagnosis built on it: a scene made to show every mistake of its catalogue, every pixel of
// an image, and the reference's settings for one with colours left unclamped.
#pragma once

#include "reference/reference_renderer.h"

#include <glm/glm.hpp>

#include <vector>

inline std::vector<glm::ivec2> everyPixel(int width, int height) {
    std::vector<glm::ivec2> pixels;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            pixels.emplace_back(i, j);
    return pixels;
}

// The default camera, depth and background at this size; colours unclamped, as the
// student model gives them.
inline ReferenceSettings unclampedSettings(int width, int height) {
    ReferenceSettings settings;
    settings.width = width;
    settings.height = height;
    settings.clampSamples = false;
    return settings;
}

// A floor whose highlight from the light above it, seen at (0, -1, -2) (the light mirrored in
// the floor, seen from the eye), lies in the shadow of the first sphere, halfway between
// that point and the light; a second sphere beyond the light from the floor below it (a
// shadow only for a tracer that ignores the light's distance); a light under the floor
// (N.L < 0 there); the floor's corners with tilted normals and their own materials; a
// second triangle, wound away from the eye, and the spheres for the highlights' shape; the light
// above bright enough that local colours pass 1 before reflections are blended, and even shininess
// on the floor so that an unclamped R.V lights it where the reflection of a light beside the eye
// points away from it.
inline constexpr const char* kMistakeScene = R"(7
amb: 0.1 0.1 0.1
light
pos: 2 1 0
col: 0.3 0.3 0.3
light
pos: 0 2 -8
col: 1.5 1.5 1.5
light
pos: 0 -3 -5
col: 0.4 0.4 0.4
sphere
pos: 0 0.5 -5
rad: 0.6
dif: 0.5 0.3 0.2
spe: 0.5 0.5 0.5
shi: 20
sphere
pos: 0 3.2 -8
rad: 1.0
dif: 0.2 0.2 0.2
spe: 0 0 0
shi: 1
triangle
pos: -4 -1 -1
nor: 0.8 1 0
dif: 0.8 0.2 0.2
spe: 0.5 0.5 0.5
shi: 2
pos: 4 -1 -1
nor: -0.8 1 0.5
dif: 0.2 0.8 0.2
spe: 0.5 0.5 0.5
shi: 2
pos: 0 -1 -10
nor: 0 1 -0.8
dif: 0.2 0.2 0.8
spe: 0.5 0.5 0.5
shi: 2
triangle
pos: 1 -0.5 -6
nor: 0 0 1
dif: 0.3 0.3 0.3
spe: 0.4 0.4 0.4
shi: 30
pos: 2 1.5 -6
nor: 0 0 1
dif: 0.3 0.3 0.3
spe: 0.4 0.4 0.4
shi: 30
pos: 3 -0.5 -6
nor: 0 0 1
dif: 0.3 0.3 0.3
spe: 0.4 0.4 0.4
shi: 30
)";
