// The texture files a model's materials name, read into the scene (Scene::textures).
#pragma once

#include "scene/scene.h"

#include <map>
#include <string>

// The largest texture side read: Vulkan's usual image limit, 16384. A header that claims
// more is refused before any pixel memory is reserved (1 GiB of RGBA8 at this size).
inline constexpr int kMaxTextureSide = 16384;

// Reads each distinct file that the meshes' materials name (MeshMaterial::diffuseTexture:
// PNG, JPEG, BMP, TGA, through stb in a child process, texture_decoder.h) and points those
// materials at it (MeshMaterial::texture).
// A texture that cannot be read (missing, a device, cut short, over kMaxTextureSide) is
// one warning naming it, the reason and how many materials keep their colour; so is a mesh
// with textured materials and no texture coordinates, whose textures are not read.
// A name starting with '*' is one of the model file's own images (GLB's), in embedded by
// name. modelFile names the model in the warnings.
void loadTextures(Scene& scene, const std::string& modelFile,
                  const std::map<std::string, std::string>& embedded = {});
