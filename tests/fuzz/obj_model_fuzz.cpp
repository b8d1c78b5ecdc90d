// libFuzzer target for the OBJ model reader (host/model/obj_reader.h, model_scene.h): any
// input must either become a scene, and its scene text, or be rejected with a SceneError.
// Anything else (another exception, a crash, a sanitizer report, a leak, a hang, unbounded
// memory) is a bug. The input is also every material library it names, so the MTL reader
// is fuzzed by the same bytes. The text read in 2 to 5 chunks at once must give the very
// model, warnings and error of one pass, or the target aborts. Also compiled into
// obj_fuzz_replay (tests/fuzz/fuzz_replay.cpp).
#include "model/model_scene.h"
#include "model/obj_reader.h"
#include "scene/scene_error.h"
#include "scene/scene_writer.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

namespace {

struct Outcome {
    std::optional<SourceModel> model; // set on success
    std::optional<SceneError> error;  // set on failure
};

Outcome read(const std::string& text, unsigned chunks) {
    Outcome outcome;
    try {
        outcome.model = parseObj(
            text, "fuzz.obj",
            [&](const std::string&) {
                return MtlFile{"fuzz.mtl", text};
            },
            ObjParseOptions{chunks, 1}); // chunks of any length: splits fall everywhere
    } catch (const SceneError& error) {
        // the expected way to reject a model; other exceptions escape and abort
        outcome.error = error;
    }
    return outcome;
}

// A model in words, every value in hex so that no bit is lost.
std::string describe(const Outcome& outcome) {
    if (outcome.error) return outcome.error->what();
    std::ostringstream out;
    out << std::hexfloat;
    const SourceModel& model = *outcome.model;
    const auto vec = [&](const auto& v) {
        for (int i = 0; i < v.length(); ++i)
            out << ' ' << v[i];
    };
    for (std::size_t i = 0; i < model.positions.size(); ++i) {
        out << "\nv";
        vec(model.positions[i]);
        out << " line " << model.positionLines[i];
        if (!model.colors.empty() && model.colors[i]) vec(*model.colors[i]);
    }
    for (const glm::dvec3& normal : model.normals)
        out << "\nvn", vec(normal);
    for (const glm::dvec2& texcoord : model.texcoords)
        out << "\nvt", vec(texcoord);
    for (std::size_t face = 0; face < faceCount(model); ++face) {
        out << "\nface";
        for (const std::uint32_t position : facePositions(model, face))
            out << ' ' << position;
    }
    for (std::size_t t = 0; t < model.triangles.size(); ++t) {
        const SourceTriangle triangle = model.triangles[t];
        out << "\ntriangle";
        for (const SourceCorner& corner : triangle.corners)
            out << ' ' << corner.position << '/' << corner.texcoord << '/'
                << (corner.normal != kNoNormal ? std::to_string(corner.normal) : "-");
        out << " material " << triangle.material << " face " << triangle.face << " line "
            << triangle.line;
    }
    for (const MeshMaterial& material : model.materials) {
        out << "\nmaterial";
        vec(material.phong.diffuse);
        vec(material.phong.specular);
        out << ' ' << material.phong.shininess << ' ' << material.phong.mirror;
        vec(material.emission);
        out << ' ' << material.diffuseTexture;
    }
    for (const auto& [what, count] : model.notRendered)
        out << "\nnot rendered: " << what << ' ' << count;
    for (const std::string& warning : model.warnings)
        out << '\n' << warning;
    return out.str();
}

void expectSameInChunks(const std::string& text, const Outcome& whole) {
    const std::string expected = describe(whole);
    for (unsigned chunks = 2; chunks <= 5; ++chunks) {
        const std::string got = describe(read(text, chunks));
        if (got == expected) continue;
        std::fprintf(stderr,
                     "obj_model_fuzz: the text read in %u chunks differs from one pass\n"
                     "--- one pass:\n%s\n--- in chunks:\n%s\n",
                     chunks, expected.c_str(), got.c_str());
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const Outcome whole = read(text, 1);
    expectSameInChunks(text, whole);
    if (!whole.model) return 0;
    try {
        const Scene scene = sceneFromModel(*whole.model, ModelSceneSetup{}, "fuzz.obj");
        (void)sceneText(scene).size();
    } catch (const SceneError&) {
        // the expected way to reject a model; other exceptions escape and abort
    }
    return 0;
}
