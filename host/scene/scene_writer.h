// A Scene written back in the scene file format (docs/model.md): what --save-scene writes,
// so that a model read from an OBJ file can be kept, edited and shared as a scene.
#pragma once

#include "scene/scene.h"

#include <filesystem>
#include <string>

// The scene as text: the count, amb:, then lights, spheres and triangles in that order.
// Numbers are written with 9 significant digits ("%.9g", -0 as 0), which every float the
// GPU is given survives; tools/obj_to_scene.py writes the same. Textured materials are
// written with the colour they have without their texture, which the format cannot hold.
std::string sceneText(const Scene& scene);

// Writes sceneText to path through a .tmp file renamed into place, so that a failure never
// leaves half a scene; throws std::runtime_error naming the file.
void writeSceneFile(const std::filesystem::path& path, const Scene& scene);

// What the scene format cannot hold of the scene, as a note to print after writing it
// ("FILE: note: the scene format holds no textures: the texture maps of 2 material(s) are
// not written", FILE the model's), or empty when it holds everything.
std::string unwrittenNote(const Scene& scene, const std::string& modelFile);
