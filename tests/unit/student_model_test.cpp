// The model of another tracer (host/compare/student_model.h): with no mistake it is the
// reference, to the bit, on every pixel; each mistake of its catalogue changes a scene made
// to show it; ambient per light adds exactly what it should.
#include "compare/student_model.h"
#include "scene/scene_loader.h"
#include "student_model_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

constexpr int kWidth = 64, kHeight = 48;

std::vector<glm::ivec2> everyPixel() {
    return ::everyPixel(kWidth, kHeight);
}

ReferenceSettings settings() {
    return unclampedSettings(kWidth, kHeight);
}

} // namespace

TEST(StudentModel, WithNoMistakeItIsTheReferenceToTheBit) {
    const Scene scene = parseScene(kMistakeScene, "model.scene");
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
    const Scene scene = parseScene(kMistakeScene, "model.scene");
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
    const Scene scene = parseScene(kMistakeScene, "model.scene");
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
