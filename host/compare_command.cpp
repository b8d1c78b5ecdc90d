#include "compare_command.h"

#include "base/image_io.h"
#include "base/parallel.h"
#include "cli/option_values.h"
#include "cli/usage_error.h"
#include "compare/compare_page.h"
#include "compare/compare_report.h"
#include "compare/comparison.h"
#include "model/scene_file.h"
#include "scene/scene_error.h"
#include "scene/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <optional>

namespace fs = std::filesystem;

namespace {

struct CompareOptions {
    fs::path mine, scene; // an image and a scene, or two folders
    bool json = false;
    bool showHelp = false;
    fs::path reportDir; // --report DIR: the HTML pages
    CompareRequest request;
};

const ChoiceNames<FovAxis>& fovAxisNames() {
    static const ChoiceNames<FovAxis> names = {{"vertical", FovAxis::Vertical},
                                               {"horizontal", FovAxis::Horizontal}};
    return names;
}
const ChoiceNames<RayPosition>& rayNames() {
    static const ChoiceNames<RayPosition> names = {{"centre", RayPosition::Centre},
                                                   {"corner", RayPosition::Corner}};
    return names;
}
const ChoiceNames<Flip>& flipNames() {
    static const ChoiceNames<Flip> names = {{"none", Flip::None},
                                            {"vertical", Flip::Vertical},
                                            {"horizontal", Flip::Horizontal},
                                            {"both", Flip::Both}};
    return names;
}
const ChoiceNames<Quantize>& quantizeNames() {
    static const ChoiceNames<Quantize> names = {{"round", Quantize::Round},
                                                {"truncate", Quantize::Truncate}};
    return names;
}

CompareOptions parseCompareOptions(const std::vector<std::string>& arguments) {
    CompareOptions options;
    FixedSettings& fixed = options.request.fixed;
    GlobalSettings& values = fixed.values;
    std::vector<std::string> positional;
    for (std::size_t k = 0; k < arguments.size(); ++k) {
        const std::string& arg = arguments[k];
        auto value = [&]() -> std::string {
            if (k + 1 >= arguments.size()) throw UsageError(arg + " expects a value");
            return arguments[++k];
        };
        if (arg == "-h" || arg == "--help") {
            options.showHelp = true;
        } else if (arg == "--json") {
            options.json = true;
        } else if (arg == "--report") {
            options.reportDir = value();
            if (options.reportDir.empty()) throw UsageError("--report expects a folder");
        } else if (arg == "--tolerance") {
            const double levels = parseReal(arg, value());
            if (levels < 0 || levels > 255)
                throw UsageError("--tolerance expects levels from 0 to 255, got " + arguments[k]);
            options.request.tolerance = levels;
        } else if (arg == "--threads") {
            options.request.threads = int(parseCount(arg, value(), 1, 1024));
        } else if (arg == "--depth") {
            values.depth = int(parseCount(arg, value(), 0, 64));
            fixed.depth = true;
        } else if (arg == "--background") {
            values.background = parseColor(arg, value());
            fixed.background = true;
        } else if (arg == "--fov") {
            values.fovDegrees = parseReal(arg, value());
            if (!(values.fovDegrees > 0 && values.fovDegrees < 180))
                throw UsageError("--fov expects degrees between 0 and 180, got " + arguments[k]);
        } else if (arg == "--fov-axis") {
            values.fovAxis = parseChoice(arg, value(), fovAxisNames());
            fixed.fovAxis = true;
        } else if (arg == "--rays") {
            values.rays = parseChoice(arg, value(), rayNames());
            fixed.rays = true;
        } else if (arg == "--flip") {
            values.flip = parseChoice(arg, value(), flipNames());
            fixed.flip = true;
        } else if (arg == "--gamma") {
            values.gamma = parseReal(arg, value());
            if (!(values.gamma >= 0.1 && values.gamma <= 10))
                throw UsageError("--gamma expects a number from 0.1 to 10, got " + arguments[k]);
            fixed.gamma = true;
        } else if (arg == "--channels") {
            if (!channelOrderFromName(value(), values.channels))
                throw UsageError("--channels expects an order of r, g and b such as rgb or bgr, "
                                 "got '" +
                                 arguments[k] + "'");
            fixed.channels = true;
        } else if (arg == "--brightness") {
            values.brightness = parseReal(arg, value());
            if (!(values.brightness > 0 && values.brightness <= 100))
                throw UsageError("--brightness expects a factor above 0, at most 100, got " +
                                 arguments[k]);
            fixed.brightness = true;
        } else if (arg == "--quantize") {
            values.quantize = parseChoice(arg, value(), quantizeNames());
            fixed.quantize = true;
        } else if (arg.size() > 1 && arg[0] == '-') {
            throw UsageError("unknown compare option " + arg);
        } else {
            positional.push_back(arg);
        }
    }
    if (options.showHelp) return options;
    if (positional.size() != 2)
        throw UsageError("compare expects an image and its scene (or a folder of images and a "
                         "folder of scenes), got " +
                         std::to_string(positional.size()) + " names");
    options.mine = positional[0];
    options.scene = positional[1];
    return options;
}

// The images compare reads, by extension.
bool looksLikeImage(const fs::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    for (const char* known : {".png", ".jpg", ".jpeg", ".ppm", ".pfm", ".exr"})
        if (extension == known) return true;
    return false;
}

// The scene for an image of a folder: SCENES/STEM.scene, else SCENES/STEM.txt or
// SCENES/STEM.obj.
std::optional<fs::path> sceneFor(const fs::path& image, const fs::path& scenes) {
    for (const char* extension : {".scene", ".txt", ".obj"}) {
        const fs::path candidate = scenes / (image.stem().string() + extension);
        std::error_code error;
        if (fs::is_regular_file(candidate, error)) return candidate;
    }
    return std::nullopt;
}

std::string sizeNote(const HandedInImage& image) {
    if (image.levels.width == 640 && image.levels.height == 480) return {};
    return "note: " + std::to_string(image.levels.width) + "x" +
           std::to_string(image.levels.height) +
           " is not the scenes' 640x480: the reference is rendered at the image's size\n";
}

// --report DIR: made (with its parents) before any work, so that a folder that cannot be
// made fails at once rather than after the comparisons.
void prepareReportFolder(const fs::path& folder) {
    std::error_code error;
    fs::create_directories(folder, error);
    if (error || !fs::is_directory(folder))
        throw std::runtime_error(folder.string() + ": cannot make the report folder" +
                                 (error ? ": " + error.message() : ": a file is in the way"));
}

void writePage(const fs::path& path, const std::string& page) {
    writeFileReplacing(path, std::vector<std::uint8_t>(page.begin(), page.end()));
}

} // namespace

std::string compareUsageText() {
    return R"(Usage: Raytracer compare IMAGE SCENE [options]
       Raytracer compare IMAGES_FOLDER SCENES_FOLDER [options]
Compares an image of SCENE made by another ray tracer with the reference (the model
of docs/model.md in double precision): first the global differences (the settings under
which the reference best matches it), then every pixel, and says where the rest is.
IMAGE: PNG, JPEG, PPM (P3 or P6), PFM or OpenEXR, of any size. A folder compares each
image with the scene of the same name (test1.jpg with test1.scene) and prints a table.

  --json                print the report as JSON (docs/compare.md has the schema)
  --report DIR          also write DIR/index.html: the report with the images, a
                        control that flips between yours and the reference, and the
                        difference as a heat map (one self-contained page; a folder
                        gets a page per image, linked from its index)
  --tolerance L         channel levels a pixel may differ by (default: 2 for an exact
                        file; a JPEG's from its estimated quality)
  --threads N           threads of the reference (default: one per core)
Settings the search would find fix them instead (each is found unless given):
  --depth D             reflection bounces, 0 to 64 (searched: 0 to 5)
  --background R,G,B    colour of rays that hit nothing
  --fov DEG             field of view in degrees (default 60; not searched)
  --fov-axis vertical|horizontal  which extent of the image --fov spans
  --rays centre|corner  eye rays through pixel centres or top-left corners
  --flip none|vertical|horizontal|both  the image's orientation
  --gamma G             the image holds colour^(1/G) (searched: 1 or 2.2)
  --channels ORDER      the image's channel order: rgb, bgr, ...
  --brightness S        the colour is multiplied by S before it is clamped
  --quantize round|truncate  floor(c*255+0.5) or floor(c*255)
  -h, --help            show this help
)";
}

int runCompareCommand(const std::vector<std::string>& arguments) {
    const CompareOptions options = parseCompareOptions(arguments);
    if (options.showHelp) {
        std::cout << compareUsageText();
        return 0;
    }
    setWorkerThreads(unsigned(options.request.threads));
    std::error_code error;
    const bool folders = fs::is_directory(options.mine, error);
    if (!folders) {
        if (fs::is_directory(options.scene, error))
            throw UsageError(options.scene.string() + " is a folder, but " + options.mine.string() +
                             " is not: compare an image with a scene, "
                             "or a folder of images with a folder of scenes");
        HandedInImage image = readHandedInImage(options.mine);
        const Scene scene = loadScene(options.scene);
        if (!options.reportDir.empty()) prepareReportFolder(options.reportDir);
        if (!options.json) std::cerr << sizeNote(image);
        const Comparison comparison = compareWithReference(options.mine, std::move(image),
                                                           options.scene, scene, options.request);
        if (!options.reportDir.empty())
            writePage(options.reportDir / "index.html", comparisonPage(comparison));
        std::cout << (options.json ? compareJson({comparison}, {}) : compareText(comparison));
        return 0;
    }
    if (!fs::is_directory(options.scene, error))
        throw UsageError(options.mine.string() + " is a folder, so " + options.scene.string() +
                         " must be the folder of its scenes");
    std::vector<fs::path> images;
    for (const fs::directory_entry& entry : fs::directory_iterator(options.mine))
        if (entry.is_regular_file() && looksLikeImage(entry.path())) images.push_back(entry.path());
    std::sort(images.begin(), images.end());
    if (images.empty())
        throw std::runtime_error(options.mine.string() +
                                 ": no images (.png, .jpg, .jpeg, .ppm, .pfm, .exr) in the folder");
    if (!options.reportDir.empty()) prepareReportFolder(options.reportDir);
    std::vector<Comparison> comparisons;
    std::vector<CompareFailure> failures;
    for (const fs::path& imagePath : images) {
        const std::optional<fs::path> scenePath = sceneFor(imagePath, options.scene);
        if (!scenePath) {
            failures.push_back({imagePath.string(), "",
                                "no scene named " + imagePath.stem().string() +
                                    ".scene (.txt, .obj) in " + options.scene.string()});
            continue;
        }
        try {
            HandedInImage image = readHandedInImage(imagePath);
            const Scene scene = loadScene(*scenePath);
            comparisons.push_back(compareWithReference(imagePath, std::move(image), *scenePath,
                                                       scene, options.request));
        } catch (const std::exception& failure) {
            failures.push_back({imagePath.string(), scenePath->string(), failure.what()});
        }
    }
    const std::string table = folderTable(comparisons, failures);
    if (!options.reportDir.empty()) {
        std::vector<std::string> pageNames;
        for (const Comparison& comparison : comparisons) {
            pageNames.push_back(comparison.imagePath.filename().string() + ".html");
            writePage(options.reportDir / pageNames.back(), comparisonPage(comparison));
        }
        writePage(options.reportDir / "index.html", folderPage(comparisons, pageNames, table));
    }
    std::cout << (options.json ? compareJson(comparisons, failures) : table);
    for (const CompareFailure& failure : failures)
        std::cerr << "error: " << failure.image << ": " << failure.message << "\n";
    return failures.empty() ? 0 : 3;
}
