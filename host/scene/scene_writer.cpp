#include "scene/scene_writer.h"

#include "scene/scene_triangles.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace {

void appendNumber(std::string& out, double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    out += std::strcmp(text, "-0") == 0 ? "0" : text;
}

void appendVector(std::string& out, const char* key, glm::dvec3 v) {
    out += key;
    for (int i = 0; i < 3; ++i) {
        out += ' ';
        appendNumber(out, v[i]);
    }
    out += '\n';
}

void appendMaterial(std::string& out, const Material& material) {
    appendVector(out, "dif:", material.diffuse);
    appendVector(out, "spe:", material.specular);
    out += "shi: ";
    appendNumber(out, material.shininess);
    out += '\n';
    if (material.mirror != 1.0) { // the classic model's share goes unsaid
        out += "mir: ";
        appendNumber(out, material.mirror);
        out += '\n';
    }
}

// The scene format holds no textures: a textured model is written with the colours its
// materials have without them (MTL's Kd, glTF's base colour factor), as
// tools/obj_to_scene.py writes it. A copy, made only when the scene has textures.
Scene withoutTextures(const Scene& scene) {
    Scene copy = scene;
    copy.textures.clear();
    for (Mesh& mesh : copy.meshes)
        for (MeshMaterial& material : mesh.materials)
            material.texture.reset();
    return copy;
}

} // namespace

std::string sceneText(const Scene& textured) {
    if (!textured.textures.empty()) return sceneText(withoutTextures(textured));
    const Scene& scene = textured;
    std::string out;
    out += std::to_string(scene.lights.size() + scene.spheres.size() + triangleCount(scene));
    out += '\n';
    appendVector(out, "amb:", scene.ambient);
    for (const Light& light : scene.lights) {
        out += "light\n";
        appendVector(out, "pos:", light.position);
        appendVector(out, "col:", light.color);
    }
    for (const Sphere& sphere : scene.spheres) {
        out += "sphere\n";
        appendVector(out, "pos:", sphere.center);
        out += "rad: ";
        appendNumber(out, sphere.radius);
        out += '\n';
        appendMaterial(out, sphere.material);
    }
    forEachTriangle(scene, [&](const Triangle& triangle) {
        out += "triangle\n";
        for (const Vertex& vertex : triangle.vertices) {
            appendVector(out, "pos:", vertex.position);
            appendVector(out, "nor:", vertex.normal);
            appendMaterial(out, vertex.material);
        }
    });
    return out;
}

void writeSceneFile(const std::filesystem::path& path, const Scene& scene) {
    const std::string text = sceneText(scene);
    const std::filesystem::path temporary = path.string() + ".tmp";
    {
        std::ofstream file(temporary, std::ios::binary);
        if (!file) {
            const std::filesystem::path folder = path.parent_path();
            std::error_code error;
            if (!folder.empty() && !std::filesystem::is_directory(folder, error))
                throw std::runtime_error("cannot write " + path.string() + ": the folder " +
                                         folder.string() + " does not exist");
            throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(errno));
        }
        file.write(text.data(), static_cast<std::streamsize>(text.size()));
        if (!file.flush()) {
            std::filesystem::remove(temporary);
            throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(errno));
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary);
        throw std::runtime_error("cannot write " + path.string() + ": " + error.message());
    }
}

std::string unwrittenNote(const Scene& scene, const std::string& modelFile) {
    std::size_t textured = 0;
    for (const Mesh& mesh : scene.meshes)
        for (const MeshMaterial& material : mesh.materials)
            textured += material.diffuseTexture.empty() ? 0 : 1;
    if (textured == 0) return {};
    return modelFile + ": note: the scene format holds no textures: the texture maps of " +
           std::to_string(textured) + " material(s) are not written";
}
