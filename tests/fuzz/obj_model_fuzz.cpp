// libFuzzer target for the OBJ model reader (host/model/obj_reader.h, model_scene.h): any
// input must either become a scene, and its scene text, or be rejected with a SceneError.
// Anything else (another exception, a crash, a sanitizer report, a leak, a hang, unbounded
// memory) is a bug. The input is also every material library it names, so the MTL reader
// is fuzzed by the same bytes. Also compiled into obj_fuzz_replay (tests/fuzz/fuzz_replay.cpp).
#include "model/model_scene.h"
#include "model/obj_reader.h"
#include "scene/scene_error.h"
#include "scene/scene_writer.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const SourceModel model = parseObj(text, "fuzz.obj", [&](const std::string&) {
            return MtlFile{"fuzz.mtl", text};
        });
        const Scene scene = sceneFromModel(model, ModelSceneSetup{}, "fuzz.obj");
        (void)sceneText(scene).size();
    } catch (const SceneError&) {
        // the expected way to reject a model; other exceptions escape and abort
    }
    return 0;
}
