#include "model/texture_files.h"

#include "model/model_paths.h"
#include "model/texture_decoder.h"
#include "scene/mapped_file.h"
#include "scene/scene_error.h"

#include <map>
#include <stdexcept>
#include <vector>

namespace {

// The bytes of a texture file, or throws std::runtime_error "FILE: REASON".
std::vector<std::uint8_t> textureFileBytes(const std::string& file) {
    try {
        const MappedFile mapped(file); // refuses devices, which would never end
        return std::vector<std::uint8_t>(mapped.text().begin(), mapped.text().end());
    } catch (const SceneError& error) {
        throw std::runtime_error(file + ": " + error.message);
    }
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
        // The files not read yet: their bytes here, then all decoded in one child.
        std::vector<TextureBytes> files;
        std::vector<std::string> names;
        auto unread = [&](const std::string& name, const std::string& problem) {
            read[name] = std::nullopt;
            scene.warnings.push_back(sceneLocation(modelFile, 0) + "warning: texture not read: " +
                                     problem + "; " + materialsKeep(users[name]));
        };
        for (const auto& [name, count] : users) {
            if (read.contains(name)) continue;
            const bool own = name.starts_with('*'); // the model file's own image
            const std::string file = own ? modelFile + " image " + name : foundFile(name);
            try {
                if (own) {
                    const auto found = embedded.find(name);
                    if (found == embedded.end())
                        throw std::runtime_error(file +
                                                 ": the model holds no such image as a file");
                    files.push_back({file, {found->second.begin(), found->second.end()}});
                } else {
                    files.push_back({file, textureFileBytes(file)});
                }
                names.push_back(name);
            } catch (const std::runtime_error& error) {
                unread(name, error.what());
            }
        }
        std::vector<DecodedTexture> decoded = decodeTextures(files, kMaxTextureSide);
        for (std::size_t i = 0; i < decoded.size(); ++i) {
            if (!decoded[i].image) {
                unread(names[i], decoded[i].problem);
                continue;
            }
            read[names[i]] = static_cast<std::uint32_t>(scene.textures.size());
            scene.textures.push_back(Texture{files[i].file, std::move(*decoded[i].image)});
        }
        for (MeshMaterial& material : mesh.materials)
            if (!material.diffuseTexture.empty()) material.texture = read[material.diffuseTexture];
    }
}
