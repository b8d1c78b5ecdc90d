// The camera options end to end: a moved camera (--camera-pos/-target/-up) renders what
// the double-precision reference sees from there, the default camera given explicitly is
// the default image byte for byte, and impossible cameras are usage errors.
#include "model/scene_file.h"
#include "scene/scene_loader.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace {

constexpr int kWidth = 160, kHeight = 120;
constexpr int kTolerance = 2;           // as the conformance tests
constexpr double kMinimumMatch = 0.995; // edges may fall either side in fp32 vs fp64

struct MovedCamera {
    std::string scene; // in the shared or project scenes
    std::string position, target, up;
};

// Readable test names and failure messages instead of gtest's byte dump.
void PrintTo(const MovedCamera& camera, std::ostream* out) {
    *out << camera.scene << " from " << camera.position << " at " << camera.target << " up "
         << camera.up;
}

std::filesystem::path findScene(const std::string& name) {
    for (const char* dir : {PROJECT_SCENES_DIR, SHARED_SCENES_DIR})
        if (std::filesystem::exists(std::filesystem::path(dir) / name))
            return std::filesystem::path(dir) / name;
    return {};
}

glm::dvec3 triple(const std::string& text) {
    glm::dvec3 value;
    std::sscanf(text.c_str(), "%lf,%lf,%lf", &value.x, &value.y, &value.z);
    return value;
}

class MovedCameraMatchesReference : public ::testing::TestWithParam<MovedCamera> {};

TEST_P(MovedCameraMatchesReference, PixelByPixel) {
    const MovedCamera& camera = GetParam();
    const std::filesystem::path scene = findScene(camera.scene);
    if (scene.empty()) GTEST_SKIP() << camera.scene << " not found";
    const std::filesystem::path dir = freshOutputDir("camera/" + scene.stem().string());
    const std::filesystem::path output = dir / "gpu.png";
    ProcessResult run =
        runRaytracer({scene.string(), "-o", output.string(), "--width", std::to_string(kWidth),
                      "--height", std::to_string(kHeight), "--validate", "--camera-pos",
                      camera.position, "--camera-target", camera.target, "--camera-up", camera.up});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_FALSE(hasValidationMessage(run)) << run.err;

    ReferenceSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    settings.cameraPosition = triple(camera.position);
    settings.cameraTarget = triple(camera.target);
    settings.cameraUp = triple(camera.up);
    const Image8 reference = renderReference(loadScene(scene), settings);
    const Image8 gpu = readPng(output);
    const ImageComparison comparison = compareImages(gpu, reference, kTolerance);
    if (comparison.fractionWithinTolerance < kMinimumMatch) {
        writePng(dir / "reference.png", reference);
        writePng(dir / "diff.png", diffImage(gpu, reference, kTolerance));
    }
    EXPECT_GE(comparison.fractionWithinTolerance, kMinimumMatch)
        << "max diff " << comparison.maxChannelDifference << " at (" << comparison.worstX << ","
        << comparison.worstY << "), images in " << dir;
    // The moved view really differs from the default one (the test could not pass by ignoring the
    // camera).
    settings.cameraPosition = {0, 0, 0};
    settings.cameraTarget = {0, 0, -1};
    settings.cameraUp = {0, 1, 0};
    EXPECT_LT(compareImages(gpu, renderReference(loadScene(scene), settings), kTolerance)
                  .fractionWithinTolerance,
              0.9);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, MovedCameraMatchesReference,
    ::testing::Values(MovedCamera{"showcase.scene", "3,4,2", "0,0,-8", "0,1,0.2"},
                      MovedCamera{"spheres.scene", "-2,1.5,1", "0.5,0,-6", "0,1,0"},
                      MovedCamera{"mesh.scene", "1,3,0.5", "0,0,-5", "0.1,1,0"},
                      MovedCamera{"table.scene", "0,-0.5,0.5", "0.3,0,-4", "0,1,0"},
                      MovedCamera{"SIGGRAPH.scene", "1,0.5,-1", "-1,0,-20", "1,1,0"}),
    [](const ::testing::TestParamInfo<MovedCamera>& param) {
        std::string name = std::filesystem::path(param.param.scene).stem().string();
        for (char& c : name)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        return name;
    });

TEST(SpecCamera, GivenExplicitlyIsTheDefaultImageByteForByte) {
    const std::filesystem::path scene = findScene("showcase.scene");
    ASSERT_FALSE(scene.empty());
    const std::filesystem::path dir = freshOutputDir("camera/spec");
    const std::vector<std::string> size = {"--width", "96", "--height", "64", "--spp", "4"};
    std::vector<std::string> plain = {scene.string(), "-o", (dir / "default.png").string()};
    plain.insert(plain.end(), size.begin(), size.end());
    std::vector<std::string> explicitSpec = {
        scene.string(), "-o",          (dir / "explicit.png").string(),
        "--camera-pos", "0,0,0",       "--camera-target",
        "0,0,-3.5",     "--camera-up", "0,2,0"};
    explicitSpec.insert(explicitSpec.end(), size.begin(), size.end());
    ASSERT_EQ(runRaytracer(plain).exitCode, 0);
    ProcessResult run = runRaytracer(explicitSpec);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(readPng(dir / "default.png").rgba, readPng(dir / "explicit.png").rgba);
}

TEST(CameraOptions, ImpossibleCamerasAreUsageErrors) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"x.scene", "--camera-pos", "1,2"}, "--camera-pos expects three numbers X,Y,Z, got '1,2'"},
        {{"x.scene", "--camera-target", "a,b,c"}, "--camera-target expects a number, got 'a'"},
        {{"x.scene", "--camera-pos", "1,1,1", "--camera-target", "1,1,1"},
         "the camera target must differ from the camera position"},
        {{"x.scene", "--camera-target", "0,5,0"},
         "the camera up vector must not be parallel to the view direction"},
        {{"x.scene", "--camera-up", "0,0,0"}, "the camera up vector must not be zero"},
    };
    for (const auto& [args, message] : cases) {
        ProcessResult run = runRaytracer(args);
        EXPECT_EQ(run.exitCode, 2) << message;
        EXPECT_NE(run.err.find("error: " + message), std::string::npos) << run.err;
    }
}

TEST(CameraOptions, HelpListsThemAndTheWindowKeys) {
    ProcessResult run = runRaytracer({"--help"});
    EXPECT_EQ(run.exitCode, 0);
    for (const char* text :
         {"--camera-pos X,Y,Z", "--camera-target X,Y,Z", "--camera-up X,Y,Z", "--shader-dir DIR",
          "--dump-shaders DIR", "R reloads", "P writes a screenshot", "V toggles vsync",
          "C or Home resets the camera"})
        EXPECT_NE(run.out.find(text), std::string::npos) << text;
}

} // namespace
