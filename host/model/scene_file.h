// A file of any kind read into a Scene: the one place that picks the reader. A model
// format is told by the file's first bytes, whatever its name (scene/file_format.h), then
// by its name: PLY and STL by the readers here, glTF, GLB and the other formats assimp
// reads through assimp_model.h, OBJ by obj_reader.h, each made a scene by the rules of
// model_scene.h (docs/models.md); anything else is scene text (scene/scene_loader.h).
#pragma once

#include "model/model_scene.h"
#include "scene/scene.h"
#include "scene/scene_capacity.h"

#include <filesystem>

// A missing, unreadable, binary or malformed file, or a device, is a SceneError naming it.
// With a capacity, a file of more triangles than it holds is refused as soon as their count
// is known: an OBJ's after its survey, before it is read; any other's before it is made a
// scene and packed.
Scene loadScene(const std::filesystem::path& path, const ModelSceneSetup& modelSetup = {},
                const SceneCapacity* capacity = nullptr);
