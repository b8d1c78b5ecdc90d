// Raytracer compare: an image made by another tracer against the reference.
//
// Each global difference is made here from a correct render, by the reference's own
// settings or by changing its pixels in this file (not by compare's code), written as a
// file, and handed to the program as a user would: the search must name exactly that
// difference, as the option that undoes it, and find every pixel matching once it is
// applied. The reference's own image matches with no difference found, as PNG, PPM (raw
// and plain), PFM and JPEG at quality 75. Bad input gets a message naming the file and a
// non-zero exit.
#include "test_support.h"

#include "base/float_image.h"
#include "base/image_io.h"
#include "compare/jpeg_codec.h"
#include "compare/jpeg_file.h"
#include "compare/student_model.h"
#include "model/scene_file.h"
#include "reference/reference_renderer.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 320, kHeight = 240;

// Coloured, lopsided (so that every flip shows), with the background in view and mirrors
// that face each other (so that each reflection depth gives another image).
constexpr const char* kSceneText = R"(8
amb: 0.1 0.1 0.1
light
pos: -2 3 0
col: 0.8 0.8 0.8
light
pos: 3 2 -1
col: 0.4 0.35 0.3
sphere
pos: -1.2 -0.3 -4
rad: 0.8
dif: 0.7 0.2 0.1
spe: 0.3 0.3 0.3
shi: 20
sphere
pos: 0.9 0.1 -5
rad: 1.0
dif: 0.05 0.05 0.2
spe: 0.85 0.85 0.85
shi: 50
sphere
pos: 0.2 -0.8 -3
rad: 0.4
dif: 0.1 0.6 0.2
spe: 0.5 0.5 0.5
shi: 10
sphere
pos: 2.2 1.3 -4.4
rad: 0.6
dif: 0.2 0.05 0.05
spe: 0.85 0.85 0.85
shi: 50
triangle
pos: -6 -1.2 -1
nor: 0 1 0
dif: 0.3 0.3 0.35
spe: 0.5 0.5 0.5
shi: 5
pos: 6 -1.2 -1
nor: 0 1 0
dif: 0.3 0.3 0.35
spe: 0.5 0.5 0.5
shi: 5
pos: 6 -1.2 -12
nor: 0 1 0
dif: 0.3 0.3 0.35
spe: 0.5 0.5 0.5
shi: 5
triangle
pos: -6 -1.2 -1
nor: 0 1 0
dif: 0.3 0.3 0.35
spe: 0.5 0.5 0.5
shi: 5
pos: 6 -1.2 -12
nor: 0 1 0
dif: 0.3 0.3 0.35
spe: 0.5 0.5 0.5
shi: 5
pos: -6 -1.2 -12
nor: 0 1 0
dif: 0.3 0.3 0.35
spe: 0.5 0.5 0.5
shi: 5
)";

fs::path writeScene(const fs::path& dir, const std::string& stem = "mirrors") {
    const fs::path path = dir / (stem + ".scene");
    writeTextFile(path, kSceneText);
    return path;
}

ReferenceSettings defaults(int width = kWidth, int height = kHeight) {
    ReferenceSettings settings;
    settings.width = width;
    settings.height = height;
    settings.clampSamples = false; // each change below decides where it clamps
    return settings;
}

double clamp01(double v) {
    return v > 0 ? std::min(v, 1.0) : 0.0;
}

// The reference's colours as bytes, through change (colour in, colour out per pixel) and
// floor(c * 255 + 0.5) or floor(c * 255).
Image8 bytesOf(const ImageF& colours, const std::function<glm::dvec3(glm::dvec3)>& change,
               bool truncate = false) {
    Image8 image;
    image.width = colours.width;
    image.height = colours.height;
    image.rgba.resize(std::size_t(image.width) * std::size_t(image.height) * 4);
    for (std::size_t p = 0; p < image.rgba.size() / 4; ++p) {
        const glm::dvec3 c =
            change({colours.rgb[3 * p], colours.rgb[3 * p + 1], colours.rgb[3 * p + 2]});
        for (int k = 0; k < 3; ++k)
            image.rgba[4 * p + std::size_t(k)] =
                std::uint8_t(std::floor(clamp01(c[k]) * 255.0 + (truncate ? 0.0 : 0.5)));
        image.rgba[4 * p + 3] = 255;
    }
    return image;
}

glm::dvec3 unchanged(glm::dvec3 c) {
    return c;
}

Image8 flipped(const Image8& image, bool vertical, bool horizontal) {
    Image8 out = image;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const int sx = horizontal ? image.width - 1 - x : x;
            const int sy = vertical ? image.height - 1 - y : y;
            for (int k = 0; k < 4; ++k)
                out.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4 +
                         std::size_t(k)] =
                    image.rgba[(std::size_t(sy) * std::size_t(image.width) + std::size_t(sx)) * 4 +
                               std::size_t(k)];
        }
    return out;
}

// The string value of "key" in JSON text (the first one), or "<absent>".
std::string jsonText(const std::string& json, const std::string& key) {
    const std::string marker = "\"" + key + "\": \"";
    const std::size_t at = json.find(marker);
    if (at == std::string::npos) return "<absent>";
    const std::size_t start = at + marker.size();
    return json.substr(start, json.find('"', start) - start);
}

// The number after "key": in JSON text, or NaN.
double jsonValue(const std::string& json, const std::string& key) {
    const std::size_t at = json.find("\"" + key + "\": ");
    if (at == std::string::npos) return std::nan("");
    return std::stod(json.substr(at + key.size() + 4));
}

ProcessResult compare(const fs::path& image, const fs::path& scene,
                      std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"compare", image.string(), scene.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return runRaytracer(args);
}

struct GlobalCase {
    const char* name;
    const char* options; // what compare must say
    std::function<Image8(const Scene&)> make;
};

ImageF render(const Scene& scene, const std::function<void(ReferenceSettings&)>& change = {}) {
    ReferenceSettings settings = defaults();
    if (change) change(settings);
    return renderReferenceFloat(scene, settings);
}

const std::vector<GlobalCase>& globalCases() {
    static const std::vector<GlobalCase> cases = {
        {"none", "", [](const Scene& s) { return bytesOf(render(s), unchanged); }},
        {"vertical_flip", "--flip vertical",
         [](const Scene& s) { return flipped(bytesOf(render(s), unchanged), true, false); }},
        {"horizontal_flip", "--flip horizontal",
         [](const Scene& s) { return flipped(bytesOf(render(s), unchanged), false, true); }},
        {"gamma", "--gamma 2.2",
         [](const Scene& s) {
             return bytesOf(render(s), [](glm::dvec3 c) {
                 for (int k = 0; k < 3; ++k)
                     c[k] = std::pow(clamp01(c[k]), 1.0 / 2.2);
                 return c;
             });
         }},
        {"bgr", "--channels bgr",
         [](const Scene& s) {
             return bytesOf(render(s), [](glm::dvec3 c) { return glm::dvec3(c.z, c.y, c.x); });
         }},
        {"depth_1", "--depth 1",
         [](const Scene& s) {
             return bytesOf(render(s, [](ReferenceSettings& r) { r.depth = 1; }), unchanged);
         }},
        {"depth_3", "--depth 3",
         [](const Scene& s) {
             return bytesOf(render(s, [](ReferenceSettings& r) { r.depth = 3; }), unchanged);
         }},
        {"black_background", "--background 0,0,0",
         [](const Scene& s) {
             return bytesOf(render(s, [](ReferenceSettings& r) { r.background = glm::dvec3(0); }),
                            unchanged);
         }},
        {"horizontal_fov", "--fov-axis horizontal",
         [](const Scene& s) {
             // 60 degrees across the width: the vertical angle with the same tangent per pixel.
             const double vertical = 2 *
                                     std::atan(std::tan(std::numbers::pi / 6) * kHeight / kWidth) *
                                     180 / std::numbers::pi;
             return bytesOf(render(s, [&](ReferenceSettings& r) { r.fovDegrees = vertical; }),
                            unchanged);
         }},
        {"corner_rays", "--rays corner",
         [](const Scene& s) {
             return bytesOf(render(s, [](ReferenceSettings& r) { r.cornerRays = true; }),
                            unchanged);
         }},
        {"truncation", "--quantize truncate",
         [](const Scene& s) { return bytesOf(render(s), unchanged, true); }},
        {"brightness", "--brightness 0.8",
         [](const Scene& s) { return bytesOf(render(s), [](glm::dvec3 c) { return c * 0.8; }); }},
    };
    return cases;
}

class GlobalDifference : public testing::TestWithParam<std::size_t> {};

} // namespace

TEST_P(GlobalDifference, IsFoundAndNamedAsTheOptionThatUndoesIt) {
    const GlobalCase& c = globalCases()[GetParam()];
    const fs::path dir = freshOutputDir(std::string("compare/global_") + c.name);
    const fs::path scenePath = writeScene(dir);
    const Scene scene = loadScene(scenePath);
    const fs::path image = dir / "mine.png";
    writePng(image, c.make(scene));
    const ProcessResult run = compare(image, scenePath, {"--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(jsonText(run.out, "options"), c.options) << run.out;
    EXPECT_EQ(jsonText(run.out, "verdict"),
              std::string(c.options).empty() ? "matches" : "matches-with-global-differences")
        << run.out;
    EXPECT_EQ(jsonValue(run.out, "matching_fraction"), 1.0) << run.out;
    // The text says the same, with the options to paste.
    const ProcessResult text = compare(image, scenePath);
    ASSERT_EQ(text.exitCode, 0) << text.err;
    if (std::string(c.options).empty())
        EXPECT_NE(text.out.find("global differences: none found"), std::string::npos) << text.out;
    else
        EXPECT_NE(text.out.find(std::string("with `") + c.options + "` on 100.00% of pixels"),
                  std::string::npos)
            << text.out;
}

INSTANTIATE_TEST_SUITE_P(Compare, GlobalDifference,
                         testing::Range(std::size_t(0), globalCases().size()),
                         [](const testing::TestParamInfo<std::size_t>& param) {
                             return std::string(globalCases()[param.param].name);
                         });

TEST(Compare, TheReferencesOwnImageMatchesInEveryFormat) {
    const fs::path dir = freshOutputDir("compare/formats");
    const fs::path scenePath = writeScene(dir);
    const Scene scene = loadScene(scenePath);
    ReferenceSettings settings = defaults();
    settings.clampSamples = true;
    const ImageF colours = renderReferenceFloat(scene, settings);
    const Image8 bytes = quantizeImage(colours);
    writePng(dir / "mine.png", bytes);
    writeFileReplacing(dir / "mine.ppm", encodePpm(dir / "mine.ppm", bytes));
    writeFileReplacing(dir / "mine.jpg", encodeJpeg(dir / "mine.jpg", bytes, 75));
    writeFileReplacing(dir / "libjpeg.jpg", encodeJpegWithLibjpeg(imageFromBytes(bytes), 75));
    writePfm(dir / "mine.pfm", colours);
    writeExr(dir / "mine.exr", colours);
    // Plain PPM, with a comment, its maximum value 255.
    std::string plain = "P3\n# made by a test\n" + std::to_string(kWidth) + " " +
                        std::to_string(kHeight) + "\n255\n";
    for (std::size_t p = 0; p < bytes.rgba.size() / 4; ++p)
        plain += std::to_string(bytes.rgba[4 * p]) + " " + std::to_string(bytes.rgba[4 * p + 1]) +
                 " " + std::to_string(bytes.rgba[4 * p + 2]) + "\n";
    writeTextFile(dir / "plain.ppm", plain);
    for (const char* name :
         {"mine.png", "mine.ppm", "plain.ppm", "mine.pfm", "mine.exr", "mine.jpg", "libjpeg.jpg"}) {
        SCOPED_TRACE(name);
        const ProcessResult run = compare(dir / name, scenePath, {"--json"});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        EXPECT_EQ(jsonText(run.out, "verdict"), "matches") << run.out;
        EXPECT_EQ(jsonText(run.out, "options"), "") << run.out;
        if (std::string(name).ends_with(".jpg")) {
            EXPECT_EQ(jsonValue(run.out, "jpeg_quality"), 75) << run.out;
            EXPECT_GT(jsonValue(run.out, "tolerance"), 2) << run.out;
        } else {
            EXPECT_EQ(jsonValue(run.out, "tolerance"), 2) << run.out;
            EXPECT_EQ(jsonValue(run.out, "matching_fraction"), 1.0) << run.out;
        }
    }
}

TEST(Compare, AJpegsQualityIsReadFromItsTables) {
    Image8 image;
    image.width = 16;
    image.height = 8;
    image.rgba.assign(16 * 8 * 4, 128);
    for (int quality : {10, 50, 75, 90, 100}) {
        const std::vector<std::uint8_t> bytes = encodeJpeg("q.jpg", image, quality);
        const JpegFacts facts = readJpegFacts("q.jpg", bytes);
        ASSERT_TRUE(facts.quality.has_value());
        EXPECT_EQ(*facts.quality, quality);
        EXPECT_TRUE(facts.exactTable);
    }
}

TEST(Compare, AnImageOfAnotherSizeIsComparedAtItsSizeWithANote) {
    const fs::path dir = freshOutputDir("compare/other_size");
    const fs::path scenePath = writeScene(dir);
    const Scene scene = loadScene(scenePath);
    writePng(dir / "small.png",
             bytesOf(renderReferenceFloat(scene, defaults(200, 150)), unchanged));
    const ProcessResult run = compare(dir / "small.png", scenePath);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("note: 200x150 is not the scenes' 640x480: the reference is rendered at "
                           "the image's size"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.out.find("verdict: matches: 100.00% of pixels"), std::string::npos) << run.out;
}

TEST(Compare, BadInputIsNamedAndFails) {
    const fs::path dir = freshOutputDir("compare/bad_input");
    const fs::path scenePath = writeScene(dir);
    const Scene scene = loadScene(scenePath);
    const std::vector<std::uint8_t> jpeg =
        encodeJpeg("x.jpg", bytesOf(renderReferenceFloat(scene, defaults()), unchanged), 90);
    writeFileReplacing(dir / "cut.jpg", std::vector<std::uint8_t>(
                                            jpeg.begin(), jpeg.begin() + long(jpeg.size() / 2)));
    writeTextFile(dir / "empty.png", "");
    writeTextFile(dir / "text.png", "hello\n");
    writeTextFile(dir / "short.ppm", "P6\n320 240\n255\nabc");
    writeTextFile(dir / "bad.ppm", "P3\n2 1\n255\n1 2 3\n4 x 6\n");
    writeTextFile(dir / "broken.scene", "1\namb: 0.1 0.1 0.1\nsphere\npos: 0 0\n");
    writePng(dir / "fine.png", bytesOf(renderReferenceFloat(scene, defaults(32, 24)), unchanged));
    struct Case {
        fs::path image, scene;
        int exitCode;
        std::string message;
    };
    const std::vector<Case> cases = {
        {dir / "cut.jpg", scenePath, 1,
         (dir / "cut.jpg").string() + ": the file is cut short: its image data has no "
                                      "end-of-image marker"},
        {dir / "empty.png", scenePath, 1, (dir / "empty.png").string() + ": the file is empty"},
        {dir / "text.png", scenePath, 1,
         (dir / "text.png").string() + ": not an image compare reads: expected PNG, JPEG, PPM"},
        {dir / "short.ppm", scenePath, 1,
         (dir / "short.ppm").string() + ": the header says 320x240 pixels, but the file ends "
                                        "after 3 bytes of them, not 230400"},
        {dir / "bad.ppm", scenePath, 1,
         (dir / "bad.ppm").string() + ":5: expected a sample value, got 'x 6"},
        {dir / "missing.png", scenePath, 1, (dir / "missing.png").string() + ": cannot open"},
        {dir / "fine.png", dir / "broken.scene", 3, (dir / "broken.scene").string() + ":4:"},
        {dir / "fine.png", dir, 2, "is a folder, but"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.image.string());
        const ProcessResult run = compare(c.image, c.scene);
        EXPECT_EQ(run.exitCode, c.exitCode) << run.err;
        EXPECT_NE(run.err.find(c.message), std::string::npos) << run.err;
        EXPECT_EQ(run.out, "");
    }
}

TEST(Compare, AFolderIsComparedImageByImageWithItsScenes) {
    const fs::path dir = freshOutputDir("compare/folder");
    const fs::path images = dir / "images", scenes = dir / "scenes";
    fs::create_directories(images);
    fs::create_directories(scenes);
    const fs::path scenePath = writeScene(scenes, "mirrors");
    writeScene(scenes, "again");
    const Scene scene = loadScene(scenePath);
    const Image8 correct = bytesOf(renderReferenceFloat(scene, defaults(64, 48)), unchanged);
    writePng(images / "mirrors.png", correct);
    writePng(images / "again.png", flipped(correct, true, false));
    writePng(images / "stray.png", correct);
    writeTextFile(images / "notes.txt", "not an image: skipped");
    const ProcessResult table = compare(images, scenes);
    EXPECT_EQ(table.exitCode, 3) << table.err;
    EXPECT_NE(table.out.find("again.png    matches-with-global-differences  100.00%   --flip "
                             "vertical"),
              std::string::npos)
        << table.out;
    EXPECT_NE(table.out.find("mirrors.png  matches"), std::string::npos) << table.out;
    EXPECT_NE(table.out.find("stray.png    error"), std::string::npos) << table.out;
    EXPECT_NE(table.err.find("stray.png: no scene named stray.scene (.txt, .obj) in"),
              std::string::npos)
        << table.err;
    const ProcessResult json = compare(images, scenes, {"--json"});
    EXPECT_EQ(json.exitCode, 3) << json.err;
    EXPECT_NE(json.out.find("\"schema\": \"raytracer-compare\", \"version\": 1"),
              std::string::npos);
    std::size_t entries = 0;
    for (std::size_t at = json.out.find("{\"image\""); at != std::string::npos;
         at = json.out.find("{\"image\"", at + 1))
        ++entries;
    EXPECT_EQ(entries, 3u) << json.out;
}

TEST(Compare, UsageErrorsNameTheOption) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"compare"}, "compare expects an image and its scene"},
        {{"compare", "a.png", "b.scene", "--flip", "sideways"},
         "--flip expects none, vertical, horizontal or both, got 'sideways'"},
        {{"compare", "a.png", "b.scene", "--channels", "rgg"},
         "--channels expects an order of r, g and b"},
        {{"compare", "a.png", "b.scene", "--width", "3"}, "unknown compare option --width"},
    };
    for (const auto& [args, message] : cases) {
        const ProcessResult run = runRaytracer(args);
        EXPECT_EQ(run.exitCode, 2);
        EXPECT_NE(run.err.find("error: " + message), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("Run 'Raytracer compare --help'"), std::string::npos) << run.err;
    }
    const ProcessResult help = runRaytracer({"compare", "--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_EQ(help.out.rfind("Usage: Raytracer compare IMAGE SCENE [options]", 0), 0u) << help.out;
}

namespace {

// Headless Chromium on a page (Debian's chromium, installed by tools/build/install_deps.sh),
// with a profile of its own and no network use, logging the page's console on stderr.
ProcessResult chromium(const fs::path& profile, const std::vector<std::string>& extra,
                       const fs::path& page) {
    std::vector<std::string> args = {"--headless",
                                     "--no-sandbox",
                                     "--disable-gpu",
                                     "--disable-quic",
                                     "--no-first-run",
                                     "--disable-background-networking",
                                     "--disable-component-update",
                                     "--disable-sync",
                                     "--user-data-dir=" + profile.string(),
                                     "--enable-logging=stderr",
                                     "--v=0"};
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back("file://" + fs::absolute(page).string());
    return runProgram("/usr/bin/chromium", args, 120);
}

// The lines of the page's console that Chromium logged (any message, an error above all).
std::vector<std::string> consoleLines(const std::string& log) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < log.size()) {
        const std::size_t end = std::min(log.find('\n', start), log.size());
        const std::string line = log.substr(start, end - start);
        if (line.find(":CONSOLE") != std::string::npos) lines.push_back(line);
        start = end + 1;
    }
    return lines;
}

} // namespace

TEST(Compare, TheReportPageShowsTheImagesAndTextInABrowserWithoutAnError) {
    const fs::path dir = freshOutputDir("compare/report");
    const fs::path scenePath = writeScene(dir);
    const Scene scene = loadScene(scenePath);
    writePng(dir / "mine.png",
             flipped(bytesOf(renderReferenceFloat(scene, defaults()), unchanged), true, false));
    const fs::path report = dir / "report";
    const ProcessResult run = compare(dir / "mine.png", scenePath, {"--report", report.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string page = readWholeFile(report / "index.html");
    ASSERT_FALSE(page.empty());
    // Self-contained: nothing from the network.
    EXPECT_EQ(page.find("http:"), std::string::npos);
    EXPECT_EQ(page.find("https:"), std::string::npos);
    EXPECT_FALSE(fs::exists(report / "index.html.tmp"));

    // The console check can fail: a page that throws is caught by it.
    writeTextFile(dir / "throws.html",
                  "<!DOCTYPE html><html><body><script>missingFunction();</script></body></html>");
    const ProcessResult throws =
        chromium(dir / "profile-throws", {"--dump-dom"}, dir / "throws.html");
    ASSERT_EQ(throws.exitCode, 0) << throws.err;
    EXPECT_FALSE(consoleLines(throws.err).empty()) << throws.err;

    // The script ran (the page marks itself ready) and the text is on it.
    const ProcessResult dom = chromium(dir / "profile-dom", {"--dump-dom"}, report / "index.html");
    ASSERT_EQ(dom.exitCode, 0) << dom.err;
    EXPECT_NE(dom.out.find("data-ready=\"yes\""), std::string::npos);
    EXPECT_NE(dom.out.find("global differences: upside down (rows in reverse order)"),
              std::string::npos);
    EXPECT_EQ(consoleLines(dom.err), std::vector<std::string>{}) << dom.err;

    // A screenshot shows the image (the red sphere's pixels) and the text (dark pixels). The
    // virtual time lets the page finish painting before the shot, whatever the machine's
    // speed (without it a large image could be caught half painted).
    const fs::path shot = dir / "screenshot.png";
    const ProcessResult screenshot = chromium(
        dir / "profile-shot",
        {"--screenshot=" + shot.string(), "--window-size=1280,1000", "--virtual-time-budget=3000"},
        report / "index.html");
    ASSERT_EQ(screenshot.exitCode, 0) << screenshot.err;
    EXPECT_EQ(consoleLines(screenshot.err), std::vector<std::string>{}) << screenshot.err;
    const Image8 image = readPng(shot);
    long red = 0, dark = 0;
    for (std::size_t p = 0; p < image.rgba.size() / 4; ++p) {
        const int r = image.rgba[4 * p], g = image.rgba[4 * p + 1], b = image.rgba[4 * p + 2];
        red += r > g + 60 && r > b + 60;
        dark += r < 80 && g < 80 && b < 80;
    }
    EXPECT_GT(red, 500) << shot;
    EXPECT_GT(dark, 2000) << shot;
}

TEST(Compare, AFoldersReportLinksAPagePerImage) {
    const fs::path dir = freshOutputDir("compare/folder_report");
    const fs::path images = dir / "images", scenes = dir / "scenes";
    fs::create_directories(images);
    fs::create_directories(scenes);
    const Scene scene = loadScene(writeScene(scenes, "one"));
    writeScene(scenes, "two");
    const Image8 correct = bytesOf(renderReferenceFloat(scene, defaults(64, 48)), unchanged);
    writePng(images / "one.png", correct);
    writePng(images / "two.png", flipped(correct, false, true));
    const ProcessResult run = compare(images, scenes, {"--report", (dir / "report").string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string index = readWholeFile(dir / "report" / "index.html");
    EXPECT_NE(index.find("<a href=\"one.png.html\">one.png</a>"), std::string::npos) << index;
    EXPECT_NE(index.find("<a href=\"two.png.html\">two.png</a>"), std::string::npos) << index;
    EXPECT_NE(readWholeFile(dir / "report" / "two.png.html").find("--flip horizontal"),
              std::string::npos);
    // A report folder that cannot be made fails before any work, and nothing is written.
    writeTextFile(dir / "file", "in the way");
    const ProcessResult blocked =
        compare(images / "one.png", scenes / "one.scene", {"--report", (dir / "file").string()});
    EXPECT_EQ(blocked.exitCode, 1);
    EXPECT_NE(blocked.err.find("cannot make the report folder"), std::string::npos) << blocked.err;
    EXPECT_EQ(blocked.out, "");
}

TEST(Compare, AnImageOfAnotherSceneIsNotExplainedBySettings) {
    const fs::path dir = freshOutputDir("compare/another_scene");
    const Scene scene = loadScene(writeScene(dir));
    writePng(dir / "mine.png", bytesOf(renderReferenceFloat(scene, defaults()), unchanged));
    const fs::path other = dir / "other.scene";
    writeTextFile(other, "2\namb: 0.2 0.2 0.2\nlight\npos: 1 2 0\ncol: 1 1 1\nsphere\npos: 0.4 0.3 "
                         "-3\nrad: 0.7\ndif: 0.2 0.4 0.8\nspe: 0.2 0.2 0.2\nshi: 10\n");
    const ProcessResult run = compare(dir / "mine.png", other, {"--json"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(jsonText(run.out, "verdict"), "differs") << run.out;
    EXPECT_EQ(jsonText(run.out, "options"), "") << run.out;
    EXPECT_LT(jsonValue(run.out, "matching_fraction"), 0.9) << run.out;
}

TEST(Compare, ARegionSaysWhatItLiesOn) {
    const fs::path dir = freshOutputDir("compare/region_facts");
    const fs::path scenePath = writeScene(dir);
    const Scene scene = loadScene(scenePath);
    Image8 image = bytesOf(renderReferenceFloat(scene, defaults()), unchanged);
    // The first sphere (line 9 of the scene), centre (-1.2, -0.3, -4), radius 0.8, lies
    // around pixel (98, 136) of 320x240 (x / -z over tan 30 degrees times the aspect);
    // a 10x10 block of it is made darker by 60 levels.
    for (int y = 131; y < 141; ++y)
        for (int x = 93; x < 103; ++x)
            for (int k = 0; k < 3; ++k) {
                std::uint8_t& byte =
                    image.rgba[(std::size_t(y) * std::size_t(kWidth) + std::size_t(x)) * 4 +
                               std::size_t(k)];
                byte = std::uint8_t(std::max(0, byte - 60));
            }
    writePng(dir / "mine.png", image);
    const ProcessResult json = compare(dir / "mine.png", scenePath, {"--json"});
    ASSERT_EQ(json.exitCode, 0) << json.err;
    EXPECT_NE(json.out.find("\"left\": 93, \"top\": 131, \"right\": 102, \"bottom\": 140, "
                            "\"pixels\": 100"),
              std::string::npos)
        << json.out;
    EXPECT_NE(json.out.find("\"traced_pixels\": 100, \"objects\": [{\"kind\": \"sphere\", "
                            "\"index\": 0, \"line\": 9, \"pixels\": 100}], "
                            "\"background_pixels\": 0"),
              std::string::npos)
        << json.out;
    const ProcessResult text =
        compare(dir / "mine.png", scenePath, {"--report", (dir / "report").string()});
    EXPECT_NE(text.out.find("1. 100 pixels in x 93-102, y 131-140: darker by 60/255 on average\n"
                            "     on the sphere of line 9 (100%)"),
              std::string::npos)
        << text.out;
    // No mistake of the catalogue darkens a block of a sphere: said so, no cause invented,
    // and its pixel's ray tree printed instead, in the text, the JSON and the page.
    EXPECT_NE(text.out.find("     cause: not explained by any known mistake"), std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("the eye ray meets the sphere of line 9\n       its terms in the "
                            "reference, and what the image implies"),
              std::string::npos)
        << text.out;
    EXPECT_NE(json.out.find("\"ray_tree\": {\"x\": "), std::string::npos) << json.out;
    EXPECT_NE(readWholeFile(dir / "report" / "index.html").find("its terms in the reference"),
              std::string::npos);
    // The page outlines it on the heat map, in percent of the image: 93/320, 131/240, ...
    EXPECT_NE(readWholeFile(dir / "report" / "index.html")
                  .find("<div class=\"region\" style=\"left:29.0625%;top:54.5833%;width:3.125%;"
                        "height:4.16667%\"><span>1</span></div>"),
              std::string::npos);
}

namespace {

// The test scene as a tracer with mistake renders it (host/compare/student_model.h), bytes
// rounded as the reference rounds them.
Image8 withMistake(const Scene& scene, Mistake mistake) {
    std::vector<glm::ivec2> pixels;
    for (int j = 0; j < kHeight; ++j)
        for (int i = 0; i < kWidth; ++i)
            pixels.emplace_back(i, j);
    const std::vector<glm::dvec3> colours = studentColours(scene, defaults(), mistake, pixels);
    ImageF image;
    image.width = kWidth;
    image.height = kHeight;
    for (const glm::dvec3& c : colours)
        image.rgb.insert(image.rgb.end(), {float(c.x), float(c.y), float(c.z)});
    return bytesOf(image, unchanged);
}

} // namespace

TEST(Compare, ARegionMadeByAClassicMistakeIsDiagnosedAsThatMistake) {
    const fs::path dir = freshOutputDir("compare/diagnosis");
    const fs::path scenePath = writeScene(dir);
    const Scene scene = loadScene(scenePath);
    for (const MistakeDescription& entry : mistakeCatalogue()) {
        if (entry.mistake != Mistake::NoShadows && entry.mistake != Mistake::BlinnPhong &&
            entry.mistake != Mistake::SpecularInShadow)
            continue;
        SCOPED_TRACE(entry.name);
        const fs::path image = dir / (std::string(entry.name) + ".png");
        writePng(image, withMistake(scene, entry.mistake));
        const ProcessResult run = compare(image, scenePath, {"--json"});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        EXPECT_EQ(jsonText(run.out, "cause"), entry.name) << run.out;
        const ProcessResult text = compare(image, scenePath);
        EXPECT_NE(text.out.find(std::string("cause: ") + entry.words), std::string::npos)
            << text.out;
    }
}
