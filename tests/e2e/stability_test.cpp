// Numerical stability: every stress scene (scenes/stress/, written by
// tools/make_stress_scenes.py, listed with its camera in scenes/stress/index.txt) rendered
// on lavapipe with each combination of the kernel's methods that matters for it
// (--sphere-test naive|stable, --triangle-test mt|watertight, --offset
// fixed|scaled|error-bound; one
// test per scene and --precision), each image compared with the CPU reference.
//
// What "wrong" means (tools/reference/reference_range.h): a pixel is wrong when some
// channel lies more than 2/255 outside the range of values the double-precision reference
// gives over the pixel-centre ray and eight rays moved 0.01 pixel from it (further only
// where a pixel is narrower than binary32 can place geometry). Knife-edge pixels, where
// the reference itself changes under that tiny move (silhouettes, shadow edges, their
// reflections), accept either side; everywhere else the range is a single value, so a
// crack, acne or a missed sphere counts. As a guard, a pixel more than 64 levels off in a
// region where the reference is smooth over the 3x3 pixels around it (wider where the
// perturbation reaches further) must never be excused.
//
// Asserted: (a) the default methods (stable, watertight, error-bound) have no wrong pixel on
// any stress scene in fp32 or fp64, at the scene's depth and at the other of 0 and 5; (b) each
// scene's must_fail combinations (a naive method where it is known to break, in fp32) have
// at least 0.1% wrong pixels, so the suite provably sees failures. Every failure rate is printed
// and written to BUILD/test-output/stability/SCENE_PRECISION.csv.
#include "test_support.h"

#include "model/scene_file.h"
#include "reference_range.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace {

constexpr int kTolerance = 2;
constexpr double kMustFailRate = 0.001;
constexpr int kGrossDifference = 64;

const std::filesystem::path kStressDir = std::filesystem::path(PROJECT_SCENES_DIR) / "stress";

using Choices = std::map<std::string, std::string>; // option (without --) -> value

struct StressScene {
    std::map<std::string, std::string> fields; // index.txt's key=value fields
    std::vector<std::string> axes;
    std::vector<Choices> mustFail;
    std::string stem() const { return std::filesystem::path(fields.at("file")).stem().string(); }
    int number(const std::string& key) const { return std::stoi(fields.at(key)); }
};

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::stringstream stream(text);
    for (std::string part; std::getline(stream, part, separator);)
        if (!part.empty()) parts.push_back(part);
    return parts;
}

std::vector<StressScene> readIndex() {
    std::vector<StressScene> scenes;
    std::ifstream file(kStressDir / "index.txt");
    for (std::string line; std::getline(file, line);) {
        if (line.empty() || line[0] == '#') continue;
        StressScene scene;
        for (const std::string& field : split(line, ' ')) {
            const std::size_t equals = field.find('=');
            scene.fields[field.substr(0, equals)] = field.substr(equals + 1);
        }
        scene.axes = split(scene.fields["axes"], ',');
        if (scene.fields["must_fail"] != "-")
            for (const std::string& entry : split(scene.fields["must_fail"], ';')) {
                Choices choices;
                for (const std::string& pair : split(entry, '+')) {
                    const std::size_t colon = pair.find(':');
                    choices[pair.substr(0, colon)] = pair.substr(colon + 1);
                }
                scene.mustFail.push_back(choices);
            }
        scenes.push_back(scene);
    }
    return scenes;
}

struct StabilityCase {
    StressScene scene;
    std::string precision;
};

// gtest prints a case by this (instead of its bytes) in test lists and failures.
void PrintTo(const StabilityCase& test, std::ostream* out) {
    *out << test.scene.stem() << " " << test.precision;
}

std::vector<StabilityCase> allCases() {
    std::vector<StabilityCase> cases;
    for (const StressScene& scene : readIndex())
        for (const char* precision : {"fp32", "fp64"})
            cases.push_back({scene, precision});
    return cases;
}

std::string caseName(const testing::TestParamInfo<StabilityCase>& info) {
    std::string name = info.param.scene.stem() + "_" + info.param.precision;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

const std::map<std::string, std::vector<std::string>> kMethodValues = {
    {"sphere-test", {"stable", "naive"}},
    {"triangle-test", {"watertight", "mt"}},
    {"offset", {"error-bound", "scaled", "fixed"}},
};
const Choices kDefaults = {
    {"sphere-test", "stable"}, {"triangle-test", "watertight"}, {"offset", "error-bound"}};

// The defaults with every listed method axis varied (precision is the test's own).
std::vector<Choices> combinations(const StressScene& scene, const std::string& precision) {
    std::vector<Choices> result = {kDefaults};
    for (const auto& [option, values] : kMethodValues) {
        if (std::find(scene.axes.begin(), scene.axes.end(), option) == scene.axes.end()) continue;
        std::vector<Choices> grown;
        for (const Choices& choices : result)
            for (const std::string& value : values) {
                Choices next = choices;
                next[option] = value;
                grown.push_back(next);
            }
        result = grown;
    }
    for (Choices& choices : result)
        choices["precision"] = precision;
    return result;
}

bool matches(const Choices& choices, const Choices& pattern) {
    for (const auto& [option, value] : pattern)
        if (choices.at(option) != value) return false;
    return true;
}

std::string label(const Choices& choices) {
    return choices.at("sphere-test") + "_" + choices.at("triangle-test") + "_" +
           choices.at("offset");
}

// Pixels more than kGrossDifference off where the reference is smooth over the pixels
// around them (3x3, or wider where the perturbation reaches further than a pixel), yet
// excused by the range: must be none (see the file comment).
long excusedGrossErrors(const Image8& image, ReferenceRange& range) {
    const Image8& centre = range.centre();
    auto at = [&](const Image8& im, int x, int y, int c) {
        return int(im.rgba[(std::size_t(y) * std::size_t(im.width) + std::size_t(x)) * 4 +
                           std::size_t(c)]);
    };
    const int reach = std::max(1, int(std::ceil(range.perturbationPixels())));
    long count = 0;
    for (int y = reach; y + reach < image.height; ++y)
        for (int x = reach; x + reach < image.width; ++x) {
            bool smooth = true, gross = false, outside = false;
            for (int c = 0; c < 3; ++c) {
                for (int dy = -reach; dy <= reach; ++dy)
                    for (int dx = -reach; dx <= reach; ++dx)
                        smooth = smooth && std::abs(at(centre, x + dx, y + dy, c) -
                                                    at(centre, x, y, c)) <= kTolerance;
                gross =
                    gross || std::abs(at(image, x, y, c) - at(centre, x, y, c)) > kGrossDifference;
            }
            if (!smooth || !gross) continue;
            for (int c = 0; c < 3; ++c)
                outside = outside || at(image, x, y, c) < range.low(x, y, c) - kTolerance ||
                          at(image, x, y, c) > range.high(x, y, c) + kTolerance;
            count += !outside;
        }
    return count;
}

class Stability : public testing::TestWithParam<StabilityCase> {};

TEST_P(Stability, DefaultsNeverFailAndNaiveMethodsFailWhereExpected) {
    const StressScene& stress = GetParam().scene;
    const std::string& precision = GetParam().precision;
    const std::filesystem::path scenePath = kStressDir / stress.fields.at("file");
    const std::filesystem::path dir = freshOutputDir("stability/" + caseName({GetParam(), 0}));

    ReferenceSettings settings;
    settings.width = stress.number("width");
    settings.height = stress.number("height");
    settings.depth = stress.number("depth");
    settings.fovDegrees = std::stod(stress.fields.at("fov"));
    const Scene scene = loadScene(scenePath);
    ReferenceRange range(scene, settings);

    const std::filesystem::path csvPath = std::filesystem::path(TEST_OUTPUT_DIR) / "stability" /
                                          (stress.stem() + "_" + precision + ".csv");
    std::ofstream csv(csvPath);
    csv << "scene,family,parameter,value,precision,sphere_test,triangle_test,offset,pixels,"
           "differing,wrong,failure_rate\n";
    // Renders with the given choices (and precision) at depth, into name.png, and counts its
    // wrong pixels against range; an empty image when the program failed (the test fails).
    auto renderAndCount = [&](const Choices& choices, const std::string& depth,
                              const std::string& name, ReferenceRange& against, Image8& image) {
        const std::filesystem::path png = dir / (name + ".png");
        std::vector<std::string> args = {scenePath.string(),
                                         "-o",
                                         png.string(),
                                         "--validate",
                                         "--width",
                                         stress.fields.at("width"),
                                         "--height",
                                         stress.fields.at("height"),
                                         "--fov",
                                         stress.fields.at("fov"),
                                         "--depth",
                                         depth};
        for (const auto& [option, value] : choices) {
            args.push_back("--" + option);
            args.push_back(value);
        }
        const ProcessResult run = runRaytracer(args);
        EXPECT_EQ(run.exitCode, 0) << name << ": " << run.err;
        EXPECT_FALSE(hasValidationMessage(run)) << run.err;
        if (run.exitCode != 0) return StabilityCount{};
        image = readPng(png);
        const StabilityCount count = countWrongPixels(image, against, kTolerance);
        std::printf("stability %s %s %-28s depth %s wrong %6.2f%% (%ld of %ld; %ld differ by "
                    "more than %d/255)\n",
                    stress.stem().c_str(), precision.c_str(), name.c_str(), depth.c_str(),
                    100.0 * count.failureRate, count.wrong, count.pixels, count.differing,
                    kTolerance);
        return count;
    };
    // What must hold: the defaults with no wrong pixel, in fp32 and fp64.
    for (const Choices& choices : combinations(stress, precision)) {
        Image8 image;
        const StabilityCount count =
            renderAndCount(choices, stress.fields.at("depth"), label(choices), range, image);
        if (HasFailure()) return;
        csv << stress.stem() << ',' << stress.fields.at("family") << ','
            << stress.fields.at("parameter") << ',' << stress.fields.at("value") << ',' << precision
            << ',' << choices.at("sphere-test") << ',' << choices.at("triangle-test") << ','
            << choices.at("offset") << ',' << count.pixels << ',' << count.differing << ','
            << count.wrong << ',' << count.failureRate << '\n';

        EXPECT_EQ(excusedGrossErrors(image, range), 0)
            << label(choices) << ": gross errors in a smooth region were excused as knife edges";
        const bool mustHold = matches(choices, kDefaults);
        bool mustFail = false;
        for (const Choices& pattern : stress.mustFail)
            mustFail = mustFail || matches(choices, pattern);
        if (mustHold) {
            EXPECT_EQ(count.wrong, 0)
                << label(choices) << " (must not fail) failed on " << stress.stem() << " in "
                << precision << ": worst pixel (" << count.worstX << "," << count.worstY << ") "
                << count.worstExcess << " levels outside the reference's range";
        }
        if (mustFail) {
            EXPECT_GE(count.failureRate, kMustFailRate)
                << label(choices) << " was expected to fail on " << stress.stem()
                << " (the scene is designed for it) but has " << count.wrong << " wrong pixels";
        }
        if (count.wrong != 0)
            writePng(dir / (label(choices) + "-wrong.png"),
                     wrongPixelImage(image, range, kTolerance));
    }
    // The defaults also at the other depth of the two the conformance suite renders every
    // scene at (0 and 5): a mirror scene without its reflections, a matte one with them.
    {
        ReferenceSettings other = settings;
        other.depth = settings.depth == 0 ? 5 : 0;
        ReferenceRange otherRange(scene, other);
        Image8 image;
        const std::string depth = std::to_string(other.depth);
        const StabilityCount count =
            renderAndCount(kDefaults, depth, "defaults-depth" + depth, otherRange, image);
        EXPECT_EQ(count.wrong, 0) << "the defaults at depth " << depth << " failed on "
                                  << stress.stem() << " in " << precision << ": worst pixel ("
                                  << count.worstX << "," << count.worstY << ")";
    }
    // Every must_fail pattern has to name a combination this test renders.
    for (const Choices& pattern : stress.mustFail) {
        if (pattern.count("precision") && pattern.at("precision") != precision) continue;
        bool rendered = false;
        for (const Choices& choices : combinations(stress, precision))
            rendered = rendered || matches(choices, pattern);
        EXPECT_TRUE(rendered) << "index.txt names a must_fail combination that is not rendered";
    }
    if (HasFailure()) {
        writePng(dir / "reference.png", range.centre());
        std::printf("images kept in %s\n", dir.c_str());
    } else {
        std::filesystem::remove_all(dir);
    }
}

INSTANTIATE_TEST_SUITE_P(StressScenes, Stability, testing::ValuesIn(allCases()), caseName);

TEST(StressScenes, IndexListsEveryScene) {
    const std::vector<StressScene> scenes = readIndex();
    ASSERT_GE(scenes.size(), 8u);
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kStressDir))
        files += entry.path().extension() == ".scene";
    EXPECT_EQ(files, scenes.size());
    for (const StressScene& scene : scenes)
        EXPECT_NO_THROW(loadScene(kStressDir / scene.fields.at("file"))) << scene.stem();
}

} // namespace
