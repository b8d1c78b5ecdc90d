#include "model/texture_files.h"

#include "model/model_paths.h"
#include "scene/mapped_file.h"
#include "scene/scene_error.h"

#include <map>
#include <stdexcept>
#include <vector>

namespace {

// The decoded texture, or throws std::runtime_error with the reason.
Image8 readTexture(const std::string& file) {
    std::vector<std::uint8_t> bytes;
    try {
        const MappedFile mapped(file); // refuses devices, which would never end
        bytes.assign(mapped.text().begin(), mapped.text().end());
    } catch (const SceneError& error) {
        throw std::runtime_error(file + ": " + error.message);
    }
    return decodeImage8(file, bytes, kMaxTextureSide);
}

// The image the model file holds under name, decoded.
Image8 decodeEmbedded(const std::string& file, const std::map<std::string, std::string>& embedded,
                      const std::string& name) {
    const auto found = embedded.find(name);
    if (found == embedded.end())
        throw std::runtime_error(file + ": the model holds no such image as a PNG or JPEG file");
    return decodeImage8(file, std::vector<std::uint8_t>(found->second.begin(), found->second.end()),
                        kMaxTextureSide);
}

std::string materialsKeep(std::size_t count) {
    return std::to_string(count) + (count == 1 ? " material keeps its" : " materials keep their") +
           " colour";
}

} // namespace

void loadTextures(Scene& scene, const std::string& modelFile,
                  const std::map<std::string, std::string>& embedded) {
    std::map<std::string, std::optional<std::uint32_t>> read; // by name: its texture, if read
    for (Mesh& mesh : scene.meshes) {
        std::map<std::string, std::size_t> users; // materials naming each file
        for (const MeshMaterial& material : mesh.materials)
            if (!material.diffuseTexture.empty()) ++users[material.diffuseTexture];
        if (users.empty()) continue;
        if (mesh.texcoords.empty()) {
            std::size_t textured = 0;
            for (const auto& [name, count] : users)
                textured += count;
            scene.warnings.push_back(sceneLocation(modelFile, 0) +
                                     "warning: textures are named but the model has no texture "
                                     "coordinates (vt): none is read; " +
                                     materialsKeep(textured));
            continue;
        }
        for (const auto& [name, count] : users) {
            if (read.contains(name)) continue;
            try {
                const bool own = name.starts_with('*'); // the model file's own image
                const std::string file = own ? modelFile + " image " + name : foundFile(name);
                Image8 image = own ? decodeEmbedded(file, embedded, name) : readTexture(file);
                read[name] = static_cast<std::uint32_t>(scene.textures.size());
                scene.textures.push_back(Texture{file, std::move(image)});
            } catch (const std::runtime_error& error) {
                read[name] = std::nullopt;
                scene.warnings.push_back(sceneLocation(modelFile, 0) +
                                         "warning: texture not read: " + error.what() + "; " +
                                         materialsKeep(count));
            }
        }
        for (MeshMaterial& material : mesh.materials)
            if (!material.diffuseTexture.empty()) material.texture = read[material.diffuseTexture];
    }
}
