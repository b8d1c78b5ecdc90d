// The scene as the file states it, in plain CPU structs (scene_loader.h reads them
// from text). No Vulkan here.
// Values are kept in double precision so that the CPU reference sees exactly the
// numbers in the file; the GPU packer rounds them to float.
#pragma once

#include "scene/mesh.h"
#include "scene/texture.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

// Each object's `line` is where its keyword stands in the file (1-based; 0 when not read
// from a file), for the pixel story's messages; the GPU never sees it. 64 bits, so the
// structs hold no padding (the fuzz test compares their bytes).
struct Sphere {
    glm::dvec3 center{0.0};
    double radius = 0.0;
    Material material;
    std::int64_t line = 0;
};

struct Vertex {
    glm::dvec3 position{0.0};
    glm::dvec3 normal{0.0}; // as given; may be unnormalised or zero
    Material material;
};

struct Triangle {
    Vertex vertices[3];
    std::int64_t line = 0;
};

struct Light {
    glm::dvec3 position{0.0};
    glm::dvec3 color{0.0};
    std::int64_t line = 0;
};

// Where an OBJ model's light rig (model/model_scene.h) hangs: the model's centre and radius.
// The rig's lights are placed from these and a camera, so that whoever renders the scene
// from another camera (a batch frame, the window) can place them again for it.
struct LightRigAnchor {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
    // The model's own lights (its emitting materials, MTL Ke), which stay where they are
    // after the rig's three.
    std::vector<Light> emitters;
};

// What an OBJ model became (model/model_scene.h), for --check, the default camera and the
// turntable: its box as read, where it was placed, and its floor.
struct ModelPlacement {
    glm::dvec3 readLow{0.0}, readHigh{0.0};     // the file's coordinates (far vertices left out)
    glm::dvec3 placedLow{0.0}, placedHigh{0.0}; // the box around its placed positions
    glm::dvec3 centre{0.0};       // its box's centre, placed: what the default camera looks at
    glm::dvec3 up{0.0, 1.0, 0.0}; // its up axis, placed: the default camera's (--view)
    bool fitted = true;           // placed for the default camera (else where its file puts it)
    bool inside = false;          // it encloses its centre: seen from inside, without a floor
    bool floor = false;           // a floor was added, with this box:
    glm::dvec3 floorLow{0.0}, floorHigh{0.0};
    // What its materials hold that is not rendered, with how many materials hold it
    // (SourceModel::notRendered).
    std::map<std::string, std::size_t> notRendered;
};

struct Scene {
    glm::dvec3 ambient{0.0};
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles; // a scene file's, each vertex with its own material
    // Models' triangles (an OBJ file's, and its floor), after the scene's own in every
    // numbering of triangles (triangleAt, scene_triangles.h).
    std::vector<Mesh> meshes;
    std::vector<Light> lights;
    // Set when lights are an OBJ model's rig, which follows the camera (docs/models.md);
    // a scene file's lights stay where the file puts them.
    std::optional<LightRigAnchor> lightRig;
    // Set for an OBJ model: where it was placed (ModelPlacement).
    std::optional<ModelPlacement> model;
    // The textures models' materials sample (MeshMaterial::texture), decoded.
    std::vector<Texture> textures;
    // Accepted oddities ("file:line: warning: ..."), printed by the caller.
    std::vector<std::string> warnings;
};
