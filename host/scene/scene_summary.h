// What --check prints of a scene that parsed: how many of each thing, and where it lies.
// No Vulkan, so it answers on a machine without a driver.
#pragma once

#include "scene/scene.h"

#include <string>

// Lines "spheres: N", "triangles: N", "lights: N", "materials: N" (distinct diffuse,
// specular and shininess triples among spheres and triangle vertices), "warnings: N" and
// "bounds: X,Y,Z to X,Y,Z" (the box around spheres and triangles, lights left out as in
// sceneBounds; "bounds: none (no spheres or triangles)" when empty), numbers in their
// shortest exact form. For an OBJ model, between bounds and warnings: "model as read:"
// (the file's coordinates), "model as placed:", "floor:" (its box, or none) and "not
// rendered:" (what its materials hold that the shading model leaves out, or nothing).
std::string sceneSummary(const Scene& scene);
