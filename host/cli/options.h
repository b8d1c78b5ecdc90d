// The command line, turned into one plain struct (README.md and --help list them);
// command_line.h writes it back.
#pragma once

#include "base/output_format.h"
#include "cli/usage_error.h"
#include "model/model_scene.h"
#include "packing/bvh.h"
#include "packing/kernel_choices.h"
#include "packing/triangle_layout.h"
#include "scene/camera.h"
#include "shared.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

// The largest --width and --height (shaders/shared.h says why).
inline constexpr std::uint32_t kMaxImageSide = MAX_IMAGE_SIDE;

struct Options {
    std::filesystem::path scenePath;
    std::filesystem::path
        outputPath; // empty: show a window (headless PNG if no display); "-": stdout
    std::uint32_t jpegQuality = kDefaultJpegQuality; // --quality Q, for a .jpg or .jpeg output only
    std::uint32_t width = 640;
    std::uint32_t height = 480;
    std::uint32_t samplesPerPixel = 1;
    std::uint32_t depth = 5; // reflection bounces after the primary hit
    glm::dvec3 background{1.0};
    double fovDegrees = 60.0;
    std::uint32_t benchFrames = 0; // > 0: --bench N
    std::string device;            // --device NAME|INDEX; empty picks the best
    std::uint32_t cpuThreads = 0;  // --threads N: the host's threads and lavapipe's; 0: defaults
    bool validate = false;         // --validate: Khronos layer on, any message fails the run
    Acceleration acceleration = Acceleration::Auto;       // --accel auto|bvh|none
    TriangleLayout triangleLayout = TriangleLayout::Auto; // --triangle-layout
    bool showHelp = false;
    bool showVersion = false; // --version: the program's, Vulkan's headers' and glslang's
    bool listDevices = false; // --list-devices: print every Vulkan device and exit
    bool quiet = false;       // --quiet: no progress, notes or warnings on stderr; errors only
    // --save-scene FILE: the scene as read (an OBJ model's as built)
    std::filesystem::path saveScenePath;
    // What an OBJ model is given (docs/models.md): --up AXIS, --crease DEG, --no-ground,
    // --view NAME, --no-fit.
    UpAxis modelUp = UpAxis::PosY;
    bool upGiven = false; // --up was given, even as y: no note that the model may lie on its back
    double creaseDegrees = 60.0;
    bool ground = true;
    ModelView modelView = ModelView::ThreeQuarter;
    bool viewGiven = false; // --view, even three-quarter: a room is then seen from outside too
    bool fit = true;
    // --terminator on|off: Hanika's shadow terminator fix; unset: on for OBJ models, off
    // for scene files (terminatorFixFor).
    std::optional<bool> terminator;
    bool checkOnly = false; // --check: parse and validate the scene, print what it holds; no Vulkan
    bool useCache = true;   // --no-cache: no shader or pipeline cache on disk
    std::uint32_t regionSide =
        0;                 // --region-size N (hidden, for tests): fixed N x N submissions; 0 adapts
    bool progress = false; // --progress: report progress even for a short render
    bool forceWindow = false;        // --window: a window or an error, never the headless fallback
    bool redrawContinuously = false; // --redraw-continuously (hidden, for the soak test)
    bool overlay = false;      // --overlay: the window opens with its overlay shown (H toggles it)
    bool samplesGiven = false; // --spp was given: the window refines up to it, not to its cap
    CameraPose
        camera; // --camera-pos, --camera-target, --camera-up (default: the camera of docs/model.md)
    bool cameraTargetGiven = false; // else the window may move the orbit pivot along the view
    bool cameraGiven = false;       // any of the three: else a fitted model's camera (cameraFor)
    std::filesystem::path shaderDirectory; // --shader-dir: compile (and watch) these sources
    std::filesystem::path dumpShadersTo;   // --dump-shaders DIR: write the embedded sources, exit
    std::uint32_t benchWindowFrames = 0;   // --bench-window N: time N progressive frames, exit
    // --snapshots K,K,...: the window writes a screenshot, as P does, when refinement of the
    // view it opens with reaches each of these sample counts (increasing, at most --spp).
    std::vector<std::uint32_t> snapshotCounts;
    KernelChoices
        kernel; // --sampler, --seed, --precision, --sphere-test, --triangle-test, --offset
    bool generalKernel = false; // --general-kernel (hidden, for tools/kernel_costs)
    bool countWork = false;     // --count-work (hidden): --bench reports the hierarchy's work
    bool storageReads = false;  // --storage-reads (hidden): the kernel's fallback read path
    // --max-storage-range and --max-allocation BYTES, --max-image-side PIXELS (hidden, for
    // tests): the device's maxStorageBufferRange, maxMemoryAllocationSize and
    // maxImageDimension2D lowered to these (gpu/limit_overrides.h).
    std::uint32_t maxStorageRange = 0;
    std::uint32_t maxAllocation = 0;
    std::uint32_t maxImageSide = 0;
    // --compare FILE: the window at FILE's size compares the render with FILE (an image of the
    // scene made by another tracer): keys show the render, FILE or the difference, I prints
    // a pixel's diagnosis (docs/compare.md).
    std::filesystem::path compareImage;
    // --pixel X,Y: print the pixel story of column X, row Y as JSON (docs/pixel_story.md);
    // headless, and alone (no PNG) without -o.
    bool pixelGiven = false;
    glm::uvec2 pixel{0};
    // Batches (docs/batches.md): the scenes after the first, rendered in the same process
    // with one device and one set of compiled kernels; -o then holds {name} or is a folder.
    std::vector<std::filesystem::path> moreScenes;
    std::uint32_t turntableFrames = 0;     // --turntable N: N frames orbiting turntableCentre
    std::optional<glm::dvec3> orbitCenter; // --orbit-center X,Y,Z: what --turntable orbits
    std::filesystem::path cameraPath;      // --camera-path FILE: one frame per camera of FILE
    bool frameRangeGiven = false; // --frames FIRST-LAST: only those frames (a farm's share)
    glm::uvec2 frameRange{0};     // first and last frame, inclusive
    // --crop X,Y,W,H: only that region of the full image, pixel for pixel as the full image has
    // it; the output is W x H.
    bool cropGiven = false;
    glm::uvec4 crop{0};

    bool operator==(const Options&) const = default; // commandLine's round trip is tested by it
};

// --accel's names, in the order --help lists them.
const ChoiceNames<Acceleration>& accelerationNames();
// --triangle-layout's names, in the order --help lists them.
const ChoiceNames<TriangleLayout>& triangleLayoutNames();
// --up's names as printed: y, -y, z, -z, x, -x.
const ChoiceNames<UpAxis>& upAxisNames();
// --view's names: three-quarter, front, back, left, right, top, bottom.
const ChoiceNames<ModelView>& modelViewNames();
// --up's value as users write it: an axis letter in either case, with an optional sign
// (z, Z, +z, -y).
UpAxis parseUpAxis(const std::string& flag, const std::string& text);

// How loadScene makes an OBJ model a scene for these options: theirs, and the view's field
// of view and aspect ratio for the framing.
ModelSceneSetup objSceneSetup(const Options& options);

Options parseOptions(int argc, const char* const* argv);

// True when the command line renders more than one image (several scenes, --turntable or
// --camera-path): host/batch.cpp renders it, headless.
bool isBatch(const Options& options);

std::string usageText();

// The line after a usage error, in place of the whole of usageText().
inline constexpr const char* kSeeHelp = "Run 'Raytracer --help' for the list of options.\n";
