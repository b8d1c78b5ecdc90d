// libFuzzer target for the model readers other than OBJ: the PLY and STL readers
// (host/model/ply_reader.h, stl_reader.h) and assimp's (assimp_model.h, in a child process) with
// the GLB framing check before it (model_file_checks.h). Any input told to be PLY, STL or GLB by
// its first bytes must either become a scene (with the images a GLB holds decoded as its
// textures) or be rejected with a SceneError. Anything
// else (another exception, a crash, a sanitizer report, a leak, a hang, unbounded memory)
// is a bug. A glTF's JSON is left out: it names files beside it.
// Also compiled into model_fuzz_replay (tests/fuzz/fuzz_replay.cpp).
#include "model/assimp_model.h"
#include "model/model_file_checks.h"
#include "model/model_scene.h"
#include "model/ply_reader.h"
#include "model/stl_reader.h"
#include "model/texture_files.h"
#include "scene/file_format.h"
#include "scene/scene_error.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    (void)glbFramingProblem(bytes);
    const auto format = otherFileFormat(bytes);
    if (!format || *format == OtherFormat::Utf16Text || *format == OtherFormat::Gltf) return 0;
    try {
        const SourceModel model = *format == OtherFormat::Ply ? readPly(bytes, "fuzz.model")
                                  : *format == OtherFormat::Stl
                                      ? readStl(bytes, "fuzz.model")
                                      : readAssimpModel(bytes, "fuzz.model", format);
        Scene scene = sceneFromModel(model, ModelSceneSetup{}, "fuzz.model");
        // The model's own images (a GLB's) decoded as textures; a file it names is not opened.
        for (Mesh& mesh : scene.meshes)
            for (MeshMaterial& material : mesh.materials)
                if (!material.diffuseTexture.starts_with('*')) material.diffuseTexture.clear();
        loadTextures(scene, "fuzz.model", model.embeddedTextures);
    } catch (const SceneError&) {
        // the expected way to reject a model; other exceptions escape and abort
    }
    return 0;
}
