// The window's keys and mouse gestures, described once: --help's section, the line the
// window prints when it opens and the table in docs/window.md and README.md (which a test
// keeps equal to windowKeysMarkdown) all come from this table. host/window/input.cpp
// handles them; a test checks that it handles exactly the keys listed here.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

struct WindowKey {
    std::string_view keys;   // as shown; several keys are joined by " or " or "/"
    std::string_view effect; // a verb phrase: "keys effect" reads as a sentence
    std::string_view detail; // more, for the docs' table only; may be empty
};

inline constexpr std::array<WindowKey, 16> kWindowKeys = {{
    {"Esc or Q", "quits", ""},
    {"R", "reloads the scene file and the shaders", ""},
    {"P", "writes a screenshot PNG of what is shown now",
     "(`SCENE-screenshot-N-Sspp.png` in the current folder, S its samples per pixel so far) and "
     "prints its path and the headless command that renders the same image (with the r2 "
     "sampler, whose samples do not depend on their count, or once refinement is done)"},
    {"Shift+P", "writes a screenshot PNG once refinement of the current view is done",
     "(so it is the headless `--spp N` image at the same settings); a camera move meanwhile "
     "makes it wait for the new view and says so; closing the window first says it was dropped "
     "and prints the headless command"},
    {"V", "toggles vsync", "(FIFO against MAILBOX, else IMMEDIATE)"},
    {"C or Home", "resets the camera", "to the default one"},
    {"O", "prints the current camera as options",
     "on stderr: `--camera-pos`, `--camera-target`, `--camera-up` and `--fov`, exact, to paste "
     "into a headless command"},
    {"left drag", "orbits", "around the scene"},
    {"wheel", "dollies", "towards or away from the orbit centre"},
    {"right drag", "looks around", "(turns the camera in place)"},
    {"W/A/S/D or Up/Left/Down/Right", "fly forward, left, back and right",
     "while held, across the scene in about 4 s"},
    {"Space/Left Control", "fly up and down",
     "while held (Control, not Shift, so that Shift+P leaves the camera where it is)"},
    {"H", "shows or hides the overlay",
     "(frame time, samples, rays per second, device; live switches for the sampler, `--spp`, "
     "`--depth`, `--precision`, `--accel` and the method choices; the camera as options to "
     "copy); never in P's screenshots; hidden unless `--overlay`"},
    {"I", "prints the story of the pixel under the mouse",
     "on stdout: its ray tree as the kernel traced it, as JSON, at the window's sample target, "
     "as `--pixel X,Y` prints it headless (docs/pixel_story.md); with `--compare`, the pixel's "
     "diagnosis instead: its colours, its region and the region's cause, the terms your image "
     "implies there (docs/compare.md)"},
    {"I + left click", "prints the story of the clicked pixel",
     "(hold I down and click; the click starts no orbit), as I does for the pixel under the "
     "mouse; stderr says `Pixel story: clicked pixel X,Y printed on stdout`"},
    {"1/2/3 or F", "with --compare, show the render, your image or the difference",
     "(F flips between the render and your image); the difference is `Raytracer compare`'s "
     "heat map: grey where a pixel matches, blue where your image is darker, red where it is "
     "brighter; P writes what is shown"},
}};

// --help's section: a heading, then one "  KEYS EFFECT" line per entry.
std::string windowKeysHelp();

// The line the window prints on stderr when it opens: "Window: Esc or Q quits; ...".
std::string windowKeysLine();

// A markdown table of every entry, with its detail.
std::string windowKeysMarkdown();

// The I key's pixel: the image pixel (column, row) under the cursor at (cursorX, cursorY) in
// window coordinates, the window being windowWidth x windowHeight screen units and its image
// imageWidth x imageHeight pixels (more than the window's units on a high-density display).
// None when the cursor is outside the window or either size is zero.
std::optional<glm::uvec2> pixelUnderCursor(double cursorX, double cursorY, int windowWidth,
                                           int windowHeight, std::uint32_t imageWidth,
                                           std::uint32_t imageHeight);
