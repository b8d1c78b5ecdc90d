// What --check prints of a scene that parsed: how many of each thing, and where it lies.
// No Vulkan, so it answers on a machine without a driver.
#pragma once

#include "scene/scene.h"

#include <string>
#include <vector>

// Lines "spheres: N", "triangles: N", "lights: N", "materials: N" (distinct diffuse,
// specular and shininess triples among spheres and triangle vertices), "warnings: N" and
// "bounds: X,Y,Z to X,Y,Z" (the box around spheres and triangles, lights left out as in
// sceneBounds; "bounds: none (no spheres or triangles)" when empty), numbers in their
// shortest exact form. For an OBJ model, between bounds and warnings: "model as read:"
// (the file's coordinates), "model as placed:", "floor:" (its box, or none) and "not
// rendered:" (what its materials hold that the shading model leaves out, or nothing).
std::string sceneSummary(const Scene& scene);

// What a model holds that the shading model does not render, with how many materials hold
// each ("texture maps (map_Kd) in 2 materials; transparency (d, Tr) in 1 material"), or
// empty when nothing (or the scene is not a model).
std::string notRenderedText(const Scene& scene);

// What loading a scene has to say, as printed after it is loaded for a render, a batch or
// the window: its warnings (summarisedWarnings), then one line naming what its model holds
// that is not rendered ("FILE: note: not rendered: ...").
std::vector<std::string> loadMessages(const Scene& scene, const std::string& fileName);
