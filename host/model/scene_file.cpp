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
#include <optional>
#include <string>

namespace {

// A model made a scene, with the textures it names, when the device holds its triangles.
Scene texturedScene(const SourceModel& model, const ModelSceneSetup& setup, const std::string& name,
                    const SceneCapacity* capacity) {
    if (capacity) checkTriangleCapacity(*capacity, model.triangles.size(), name);
    const PhaseTimer timer("model");
    Scene scene = sceneFromModel(model, setup, name);
    loadTextures(scene, name, model.embeddedTextures);
    return scene;
}

// The file read by a model reader: the "read" phase.
template <typename Read> SourceModel timedRead(Read read) {
    const PhaseTimer timer("read");
    return read();
}

} // namespace

Scene loadScene(const std::filesystem::path& path, const ModelSceneSetup& modelSetup,
                const SceneCapacity* capacity) {
    const std::string name = path.string();
    std::error_code error;
    // open succeeds on a directory on Linux and only the read fails; say it plainly.
    if (std::filesystem::is_directory(path, error))
        throw SceneError(name, 0, std::string("cannot open file: ") + std::strerror(EISDIR));
    const MappedFile file(name);
    const std::optional<OtherFormat> format = otherFileFormat(file.text());
    if (format == OtherFormat::Ply || (!format && isPlyPath(path)))
        return texturedScene(timedRead([&] { return readPly(file.text(), name); }), modelSetup,
                             name, capacity);
    if (format == OtherFormat::Stl || (!format && isStlPath(path)))
        return texturedScene(timedRead([&] { return readStl(file.text(), name); }), modelSetup,
                             name, capacity);
    if (format && *format != OtherFormat::Utf16Text)
        return texturedScene(timedRead([&] { return readAssimpModel(file.text(), path, format); }),
                             modelSetup, name, capacity);
    if (isObjPath(path))
        return texturedScene(timedRead([&] { return readObjFile(path, file.text(), capacity); }),
                             modelSetup, name, capacity);
    if (isAssimpPath(path) && !format)
        return texturedScene(
            timedRead([&] { return readAssimpModel(file.text(), path, std::nullopt); }), modelSetup,
            name, capacity);
    Scene scene = [&] {
        const PhaseTimer timer("read");
        return parseScene(file.text(), name);
    }();
    if (capacity) checkTriangleCapacity(*capacity, scene.triangles.size(), name);
    return scene;
}
