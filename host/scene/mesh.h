// A triangle mesh indexed as model files store one (pbrt-v4's TriangleMesh, a glTF
// primitive): vertices shared by the triangles that meet there, and a material per triangle
// from the mesh's table. Models of any format become one of these (model_scene.h for OBJ);
// the scene format, which states a material per vertex, keeps its per-vertex Triangle
// (scene.h). Packing reads both (host/packing/scene_packing.h). No Vulkan here.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

struct Material {
    glm::dvec3 diffuse{0.0};  // kd, "dif:"
    glm::dvec3 specular{0.0}; // ks, "spe:"
    double shininess = 0.0;   // Phong exponent, "shi:"
    // The share of ks that is the mirror weight of the reflection, "mir:" (optional, 0 to
    // 1): 1 in the classic model, where ks is both; 0 for a highlight without a mirror
    // (MTL illum 2).
    double mirror = 1.0;
};

// The weight of the mirror reflection: ks times the mirror share (ks itself, to the bit,
// in the classic model).
inline glm::dvec3 mirrorWeight(const Material& material) {
    return material.specular * material.mirror;
}

// One entry of a mesh's material table.
struct MeshMaterial {
    Material phong;
    // The diffuse texture the model names: OBJ's map_Kd file, found from its MTL file's
    // folder; a glTF base colour texture from the glTF file's. Empty: none.
    std::string diffuseTexture;
    // The texture once read (Scene::textures' index, model/texture_files.h): the diffuse
    // colour is then the texture's at the hit times textureFactor (1 for MTL, whose map_Kd
    // takes the place of Kd; glTF's base colour factor), and phong.diffuse is unused. None:
    // no texture, or one that could not be read, and phong.diffuse is the colour.
    std::optional<std::uint32_t> texture;
    glm::dvec3 textureFactor{1.0};
    // MTL's Ke, negative parts 0: a model's emitting surfaces become point lights
    // (model/model_scene.h). Zero: the material emits nothing.
    glm::dvec3 emission{0.0};
};

struct Mesh {
    // Every vertex is a corner of some triangle. Per vertex: its position in the scene and its
    // shading normal (as given or computed for the model; not necessarily of unit length).
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;
    // Per vertex, or empty when the model has none: texture coordinates (u, v), v up: (0, 0)
    // is the image's bottom left corner, as OBJ's vt has it (glTF's are turned to this).
    std::vector<glm::dvec2> texcoords;
    // Per vertex, or empty when no vertex has one: a diffuse colour in rgb that replaces the
    // triangles' kd at that vertex where a is 1 (OBJ's `v x y z r g b`); a 0 keeps theirs.
    std::vector<glm::dvec4> colors;
    // Per triangle: its three vertices, its material (into materials) and the line of the
    // model file that states it (for the pixel story; 0 when none).
    std::vector<glm::uvec3> triangles;
    std::vector<std::uint32_t> triangleMaterials;
    std::vector<std::int64_t> triangleLines;
    std::vector<MeshMaterial> materials;
};

// The material at vertex v of triangle t: the triangle's, with the vertex's colour as kd
// where it has one. A textured material's kd is what multiplies the texture's colour: its
// textureFactor, times the vertex's colour where it has one (as glTF's COLOR_0 does).
inline Material cornerMaterial(const Mesh& mesh, std::size_t t, std::uint32_t v) {
    const MeshMaterial& meshMaterial = mesh.materials[mesh.triangleMaterials[t]];
    Material material = meshMaterial.phong;
    const bool colored = !mesh.colors.empty() && mesh.colors[v].w == 1.0;
    if (meshMaterial.texture)
        material.diffuse =
            meshMaterial.textureFactor * (colored ? glm::dvec3(mesh.colors[v]) : glm::dvec3(1.0));
    else if (colored)
        material.diffuse = glm::dvec3(mesh.colors[v]);
    return material;
}

// The texture of triangle t's material (Scene::textures' index), if it has one.
inline std::optional<std::uint32_t> triangleTexture(const Mesh& mesh, std::size_t t) {
    return mesh.materials[mesh.triangleMaterials[t]].texture;
}

// Vertex v's texture coordinates: (0, 0) when the mesh has none.
inline glm::dvec2 vertexTexcoord(const Mesh& mesh, std::uint32_t v) {
    return mesh.texcoords.empty() ? glm::dvec2(0.0) : mesh.texcoords[v];
}
