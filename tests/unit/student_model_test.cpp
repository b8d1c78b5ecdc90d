// The model of another tracer (host/compare/student_model.h): with no mistake it is the
// reference, to the bit, on every pixel; each mistake of its catalogue changes a scene made
// to show it; ambient per light adds exactly what it should.
#include "compare/student_model.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

// A floor whose highlight from the light above it, seen at (0, -1, -2) (the light mirrored in
// the floor, seen from the eye), lies in the shadow of the first sphere, halfway between
// that point and the light; a second sphere beyond the light from the floor below it (a
// shadow only for a tracer that ignores the light's distance); a light under the floor
// (N.L < 0 there); the floor's corners with tilted normals and their own materials; a
// second triangle and the spheres for the highlights' shape; the light above bright enough
// that local colours pass 1 before reflections are blended, and even shininess on the floor
// so that an unclamped R.V lights it where the reflection of a light beside the eye points
// away from it.
constexpr const char* kScene = R"(7
amb: 0.1 0.1 0.1
light
pos: 2 1 0
col: 0.3 0.3 0.3
light
pos: 0 2 -8
col: 1.5 1.5 1.5
light
pos: 0 -3 -5
col: 0.4 0.4 0.4
sphere
pos: 0 0.5 -5
rad: 0.6
dif: 0.5 0.3 0.2
spe: 0.5 0.5 0.5
shi: 20
sphere
pos: 0 3.2 -8
rad: 1.0
dif: 0.2 0.2 0.2
spe: 0 0 0
shi: 1
triangle
pos: -4 -1 -1
nor: 0.8 1 0
dif: 0.8 0.2 0.2
spe: 0.5 0.5 0.5
shi: 2
pos: 4 -1 -1
nor: -0.8 1 0.5
dif: 0.2 0.8 0.2
spe: 0.5 0.5 0.5
shi: 2
pos: 0 -1 -10
nor: 0 1 -0.8
dif: 0.2 0.2 0.8
spe: 0.5 0.5 0.5
shi: 2
triangle
pos: 1 -0.5 -6
nor: 0 0 1
dif: 0.3 0.3 0.3
spe: 0.4 0.4 0.4
shi: 30
pos: 3 -0.5 -6
nor: 0 0 1
dif: 0.3 0.3 0.3
spe: 0.4 0.4 0.4
shi: 30
pos: 2 1.5 -6
nor: 0 0 1
dif: 0.3 0.3 0.3
spe: 0.4 0.4 0.4
shi: 30
)";

constexpr int kWidth = 64, kHeight = 48;

std::vector<glm::ivec2> everyPixel() {
    std::vector<glm::ivec2> pixels;
    for (int j = 0; j < kHeight; ++j)
        for (int i = 0; i < kWidth; ++i)
            pixels.emplace_back(i, j);
    return pixels;
}

ReferenceSettings settings() {
    ReferenceSettings s;
    s.width = kWidth;
    s.height = kHeight;
    s.clampSamples = false;
    return s;
}

} // namespace

TEST(StudentModel, WithNoMistakeItIsTheReferenceToTheBit) {
    const Scene scene = parseScene(kScene, "model.scene");
    for (int depth : {0, 1, 5}) {
        ReferenceSettings s = settings();
        s.depth = depth;
        const ImageF reference = renderReferenceFloat(scene, s);
        const std::vector<glm::dvec3> model = studentColours(scene, s, Mistake::None, everyPixel());
        for (std::size_t p = 0; p < model.size(); ++p)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(float(model[p][c]), reference.rgb[3 * p + std::size_t(c)])
                    << "pixel " << p << " channel " << c << " depth " << depth;
    }
}

TEST(StudentModel, EachMistakeChangesTheSceneMadeToShowIt) {
    const Scene scene = parseScene(kScene, "model.scene");
    const std::vector<glm::dvec3> right =
        studentColours(scene, settings(), Mistake::None, everyPixel());
    for (const MistakeDescription& entry : mistakeCatalogue()) {
        SCOPED_TRACE(entry.name);
        const std::vector<glm::dvec3> wrong =
            studentColours(scene, settings(), entry.mistake, everyPixel());
        long changed = 0;
        for (std::size_t p = 0; p < wrong.size(); ++p) {
            const glm::dvec3 a = glm::clamp(right[p], 0.0, 1.0), b = glm::clamp(wrong[p], 0.0, 1.0);
            changed += glm::any(glm::greaterThan(glm::abs(a - b), glm::dvec3(2.0 / 255)));
        }
        // At least 1% of the image.
        EXPECT_GT(changed, kWidth * kHeight / 100) << entry.words;
    }
}

TEST(StudentModel, AmbientPerLightAddsTheAmbientOncePerExtraLight) {
    // Ambient per light adds the ambient once more for each light after the first, wherever
    // the point is (here on the floor in the first sphere's shadow).
    const Scene scene = parseScene(kScene, "model.scene");
    ReferenceSettings s = settings();
    s.depth = 0;
    const glm::ivec2 shadow{32, 44}; // (0, -1, -2): y / -z = -0.5 over tan 30 degrees
    const glm::dvec3 right = studentColours(scene, s, Mistake::None, {shadow}).front();
    const glm::dvec3 wrong = studentColours(scene, s, Mistake::AmbientPerLight, {shadow}).front();
    const glm::dvec3 noShadow = studentColours(scene, s, Mistake::NoShadows, {shadow}).front();
    EXPECT_GT(noShadow.x, right.x + 0.05) << "the pixel is not in the sphere's shadow";
    const double extra = 0.1 * double(scene.lights.size() - 1);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(wrong[c] - right[c], extra, 1e-12);
}
