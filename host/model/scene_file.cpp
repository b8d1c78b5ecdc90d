#include "model/scene_file.h"

#include "base/startup_phases.h"
#include "model/assimp_model.h"
#include "model/obj_reader.h"
#include "model/ply_reader.h"
#include "model/stl_reader.h"
#include "model/texture_files.h"
#include "scene/file_format.h"
#include "scene/mapped_file.h"
#include "scene/scene_error.h"
#include "scene/scene_loader.h"

#include <cerrno>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace {

// A model made a scene, with the textures it names, when the device holds its triangles.
Scene texturedScene(SourceModel&& model, const ModelSceneSetup& setup, const std::string& name,
                    const SceneCapacity* capacity) {
    if (capacity) checkTriangleCapacity(*capacity, model.triangles.size(), name);
    const PhaseTimer timer("model");
    const std::map<std::string, std::string> embeddedTextures = std::move(model.embeddedTextures);
    Scene scene = sceneFromModel(std::move(model), setup, name);
    loadTextures(scene, name, embeddedTextures);
    return scene;
}

// A file read: a model's, which is then made a scene, or a scene file's scene.
using FileContents = std::variant<SourceModel, Scene>;

// The file at path read by the reader its first bytes, else its name, call for: the "read"
// phase.
FileContents readFile(const std::filesystem::path& path, const MappedFile& file,
                      const SceneCapacity* capacity) {
    const PhaseTimer timer("read");
    const std::string name = path.string();
    const std::optional<OtherFormat> format = otherFileFormat(file.text());
    if (format == OtherFormat::Ply || (!format && isPlyPath(path)))
        return readPly(file.text(), name);
    if (format == OtherFormat::Stl || (!format && isStlPath(path)))
        return readStl(file.text(), name);
    if (format && *format != OtherFormat::Utf16Text)
        return readAssimpModel(file.text(), path, format);
    if (isObjPath(path)) return readObjFile(path, file.text(), capacity);
    if (isAssimpPath(path) && !format) return readAssimpModel(file.text(), path, std::nullopt);
    return parseScene(file.text(), name);
}

} // namespace

Scene loadScene(const std::filesystem::path& path, const ModelSceneSetup& modelSetup,
                const SceneCapacity* capacity) {
    const std::string name = path.string();
    std::error_code error;
    // open succeeds on a directory on Linux and only the read fails; say it plainly.
    if (std::filesystem::is_directory(path, error))
        throw SceneError(name, 0, std::string("cannot open file: ") + std::strerror(EISDIR));
    // The file is unmapped once read: a large model's pages (as many bytes as the file)
    // are not held through the model phase, the start-up's peak of memory.
    FileContents contents = [&] {
        const MappedFile file(name);
        return readFile(path, file, capacity);
    }();
    if (SourceModel* model = std::get_if<SourceModel>(&contents))
        return texturedScene(std::move(*model), modelSetup, name, capacity);
    Scene& scene = std::get<Scene>(contents);
    if (capacity) checkTriangleCapacity(*capacity, scene.triangles.size(), name);
    return std::move(scene);
}
