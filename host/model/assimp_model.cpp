#include "model/assimp_model.h"

#include "model/contained_reader.h"
#include "model/model_file_checks.h"
#include "model/model_paths.h"
#include "model/polygon_triangulation.h"
#include "model/shared_positions.h"
#include "scene/scene_error.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>

namespace {

// A Phong material from an assimp one (docs/models.md): kd the base or diffuse colour; a
// metallic-roughness material (glTF) a highlight of the dielectric 0.04 blended towards the
// base colour by metallic, faded by roughness, its exponent 2 / roughness^4 - 2; another a
// specular colour and exponent as given; exponents clamped as MTL's Ns; no mirror.
MeshMaterial materialFrom(const aiMaterial& source, const std::string& modelFile,
                          std::map<std::string, std::size_t>& counted) {
    MeshMaterial material = defaultModelMaterial();
    aiColor4D colour;
    const bool baseColour = source.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS;
    if (baseColour || source.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS)
        material.phong.diffuse = glm::clamp(glm::dvec3(colour.r, colour.g, colour.b), 0.0, 1.0);
    ai_real metallic = 0, roughness = 1, shininess = 0;
    if (source.Get(AI_MATKEY_METALLIC_FACTOR, metallic) == AI_SUCCESS) {
        source.Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness);
        const double m = std::clamp(double(metallic), 0.0, 1.0),
                     r = std::clamp(double(roughness), 0.01, 1.0);
        material.phong.specular =
            (glm::dvec3(0.04) * (1.0 - m) + material.phong.diffuse * m) * (1.0 - r);
        material.phong.shininess = 2.0 / (r * r * r * r) - 2.0;
    } else {
        aiColor3D specular;
        if (source.Get(AI_MATKEY_COLOR_SPECULAR, specular) == AI_SUCCESS)
            material.phong.specular =
                glm::clamp(glm::dvec3(specular.r, specular.g, specular.b), 0.0, 1.0);
        if (source.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS)
            material.phong.shininess = shininess;
    }
    material.phong.shininess =
        std::clamp(material.phong.shininess, kMinModelShininess, kMaxModelShininess);
    material.phong.mirror = 0.0;
    aiColor3D emissive;
    if (source.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == AI_SUCCESS)
        material.emission = glm::max(glm::dvec3(emissive.r, emissive.g, emissive.b), 0.0);
    aiString texture;
    if (source.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS ||
        source.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS) {
        // A name of the file's own textures ("*0") as it is; a file's from the model's folder.
        const std::string named = texture.C_Str();
        material.diffuseTexture = named.starts_with('*') ? named : besideFile(modelFile, named);
        // glTF's base colour is its factor times the texture; other formats' diffuse colour
        // is what the texture takes the place of, as MTL's Kd.
        if (baseColour) material.textureFactor = material.phong.diffuse;
    }
    // A value that is not finite (a damaged file) falls back to the default material's.
    const MeshMaterial fallback = defaultModelMaterial();
    auto finite = [](glm::dvec3 v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    if (!finite(material.phong.diffuse)) material.phong.diffuse = fallback.phong.diffuse;
    if (!finite(material.phong.specular)) material.phong.specular = fallback.phong.specular;
    if (!std::isfinite(material.phong.shininess))
        material.phong.shininess = fallback.phong.shininess;
    if (!finite(material.emission)) material.emission = fallback.emission;
    if (!finite(material.textureFactor)) material.textureFactor = fallback.textureFactor;
    ai_real opacity = 1;
    if (source.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && opacity < 1)
        ++counted["transparency"];
    for (const aiTextureType other :
         {aiTextureType_NORMALS, aiTextureType_HEIGHT, aiTextureType_METALNESS,
          aiTextureType_DIFFUSE_ROUGHNESS, aiTextureType_EMISSIVE, aiTextureType_SPECULAR}) {
        if (source.GetTextureCount(other) > 0) {
            ++counted["other maps (normal, metallic-roughness, ...)"];
            break;
        }
    }
    return material;
}

// The files a model names (a glTF's buffers) are opened only when they are regular files:
// a device (/dev/zero) would be read without end.
class RegularFilesOnly : public Assimp::DefaultIOSystem {
  public:
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        std::error_code error;
        if (!std::filesystem::is_regular_file(file, error)) return nullptr;
        return DefaultIOSystem::Open(file, mode);
    }
};

} // namespace

namespace {

SourceModel readInThisProcess(std::string_view bytes, const std::filesystem::path& path,
                              std::optional<OtherFormat> format) {
    const std::string name = path.string();
    Assimp::Importer importer;
    importer.SetIOHandler(new RegularFilesOnly); // the importer owns it
    // Points and lines are dropped; meshes are put where their nodes' transforms place them.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const unsigned flags =
        aiProcess_ValidateDataStructure | aiProcess_PreTransformVertices | aiProcess_SortByPType;
    const char* hint = format == OtherFormat::BinaryGltf ? "glb" : nullptr;
    // Self-contained formats are read from the bytes already mapped; others (a .gltf with
    // its buffers and images beside it, FBX, COLLADA) from the path.
    const aiScene* scene =
        hint ? importer.ReadFileFromMemory(bytes.data(), bytes.size(), flags, hint)
             : importer.ReadFile(name, flags);
    if (!scene || !scene->mRootNode) {
        std::string reason = importer.GetErrorString();
        // assimp names the file it read from memory by a placeholder: say it plainly.
        if (reason.starts_with("No suitable reader found"))
            reason = "assimp found no reader that accepts it";
        throw SceneError(name, 0, "cannot read the model: " + reason);
    }

    SourceModel model;
    // Material i of the file is model material i + 1 (0 is the default one).
    model.materials.push_back(defaultModelMaterial());
    for (unsigned i = 0; i < scene->mNumMaterials; ++i)
        model.materials.push_back(materialFrom(*scene->mMaterials[i], name, model.notRendered));
    // The file's own images, as the bytes of their files (PNG, JPEG); an image stored as raw
    // texels (mHeight > 0, rare) is left out and then named as not read.
    for (unsigned i = 0; i < scene->mNumTextures; ++i) {
        const aiTexture& texture = *scene->mTextures[i];
        if (texture.mHeight == 0 && texture.pcData)
            model.embeddedTextures["*" + std::to_string(i)] =
                std::string(reinterpret_cast<const char*>(texture.pcData), texture.mWidth);
    }
    SharedPositions shared(model, 1024);
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh& mesh = *scene->mMeshes[m];
        std::vector<std::uint32_t> position(mesh.mNumVertices);
        const bool colours = mesh.HasVertexColors(0);
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D& p = mesh.mVertices[v];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw SceneError(name, 0,
                                 "vertex " + std::to_string(v + 1) + " of mesh " +
                                     std::to_string(m + 1) + " is not a finite position");
            std::optional<glm::vec3> colour;
            if (colours) {
                const aiColor4D& c = mesh.mColors[0][v];
                colour = glm::vec3(c.r, c.g, c.b);
            }
            position[v] = shared.add(glm::vec3(p.x, p.y, p.z), colour, 0);
        }
        const std::uint32_t normalBase = static_cast<std::uint32_t>(model.normals.size());
        // Normals as given, unless one is not finite: then the crease rule's for the mesh.
        bool normals = mesh.HasNormals();
        for (unsigned v = 0; normals && v < mesh.mNumVertices; ++v)
            normals = std::isfinite(mesh.mNormals[v].x) && std::isfinite(mesh.mNormals[v].y) &&
                      std::isfinite(mesh.mNormals[v].z);
        if (normals)
            for (unsigned v = 0; v < mesh.mNumVertices; ++v)
                model.normals.emplace_back(mesh.mNormals[v].x, mesh.mNormals[v].y,
                                           mesh.mNormals[v].z);
        // Texture coordinates as given (v up: assimp turns glTF's v down to it), unless one is
        // not finite: then the mesh has none.
        const std::uint32_t texcoordBase = static_cast<std::uint32_t>(model.texcoords.size());
        bool texcoords = mesh.HasTextureCoords(0);
        for (unsigned v = 0; texcoords && v < mesh.mNumVertices; ++v)
            texcoords = std::isfinite(mesh.mTextureCoords[0][v].x) &&
                        std::isfinite(mesh.mTextureCoords[0][v].y);
        if (texcoords)
            for (unsigned v = 0; v < mesh.mNumVertices; ++v)
                model.texcoords.emplace_back(mesh.mTextureCoords[0][v].x,
                                             mesh.mTextureCoords[0][v].y);
        const std::uint32_t material = mesh.mMaterialIndex + 1;
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices < 3) continue;
            std::vector<SourceCorner> corners;
            std::vector<glm::dvec3> points;
            std::vector<std::uint32_t> cornerPositions;
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                const unsigned v = face.mIndices[k];
                SourceCorner corner;
                corner.position = position[v];
                if (normals) corner.normal = normalBase + v;
                if (texcoords) corner.texcoord = texcoordBase + v;
                corners.push_back(corner);
                points.push_back(model.positions[corner.position]);
                cornerPositions.push_back(corner.position);
            }
            const std::uint32_t faceIndex = addFace(model, cornerPositions);
            if (corners.size() == 3) {
                model.triangles.push_back(
                    {{corners[0], corners[1], corners[2]}, material, faceIndex, 0});
                continue;
            }
            const PolygonTriangles split = triangulatePolygon(points);
            for (const auto& [a, b, c] : split.triangles)
                model.triangles.push_back(
                    {{corners[a], corners[b], corners[c]}, material, faceIndex, 0});
        }
    }
    if (model.triangles.empty())
        throw SceneError(name, 0, "no faces found (points and lines are not rendered)");
    return model;
}

} // namespace

SourceModel readAssimpModel(std::string_view bytes, const std::filesystem::path& path,
                            std::optional<OtherFormat> format) {
    const std::string name = path.string();
    if (format == OtherFormat::BinaryGltf)
        if (const auto problem = glbFramingProblem(bytes)) throw SceneError(name, 0, *problem);
    return readContained(name, [&] { return readInThisProcess(bytes, path, format); });
}
