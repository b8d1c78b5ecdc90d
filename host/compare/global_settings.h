// The global differences an image of a scene can have from the reference: settings that
// change every pixel alike (the reflection depth, the background, the camera's field of
// view and rays, how colours become bytes, the image's orientation). The search
// (global_search.h) finds the settings under which the reference best matches an image;
// they are reported as the compare command's own options, which also fix them.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <string>

struct ReferenceSettings;

enum class FovAxis { Vertical, Horizontal }; // which extent of the image --fov spans
enum class RayPosition { Centre, Corner };   // where in its pixel the eye ray passes
enum class Flip { None, Vertical, Horizontal, Both };
enum class Quantize { Round, Truncate }; // floor(c * 255 + 0.5) or floor(c * 255)

struct GlobalSettings {
    int depth = 5;
    glm::dvec3 background{1.0};
    double fovDegrees = 60;
    FovAxis fovAxis = FovAxis::Vertical;
    RayPosition rays = RayPosition::Centre;
    Flip flip = Flip::None;
    double gamma = 1.0; // the image holds c^(1/gamma)
    // The image's channel k holds the reference's channel channels[k]: {0,1,2} is RGB,
    // {2,1,0} BGR.
    std::array<int, 3> channels{0, 1, 2};
    double brightness = 1.0; // the colour is multiplied by this before it is clamped
    Quantize quantize = Quantize::Round;
};

// "rgb", "bgr", ...: the channel order's name, and its inverse (false for anything else).
std::string channelOrderName(const std::array<int, 3>& channels);
bool channelOrderFromName(const std::string& name, std::array<int, 3>& channels);
const char* flipName(Flip flip);
const char* fovAxisName(FovAxis axis);
const char* rayPositionName(RayPosition rays);
const char* quantizeName(Quantize quantize);

// How many settings differ from the defaults (the model's own: docs/model.md).
int departures(const GlobalSettings& settings);

// The settings that differ from the defaults as compare options, in a fixed order:
// "--depth 3 --background 0,0,0"; empty when there are none.
std::string departureOptions(const GlobalSettings& settings);

// The same in words, one phrase each: "3 reflection bounces", "the image is upside down".
std::string departureWords(const GlobalSettings& settings);

// A number as the options print it: at most 3 decimals, no trailing zeros ("0.2", "60").
std::string shortNumber(double value);

// The reference's settings for an image of width x height under these settings (the
// depth, background, field of view and ray position; the rest applies to its colours).
ReferenceSettings referenceSettingsFor(const GlobalSettings& settings, int width, int height);

// The level 0..255 an image under these settings holds for a reference colour channel c
// (unclamped): brightness, clamp to [0, 1], gamma, then rounding or truncation.
double presentedLevel(const GlobalSettings& settings, double c);

// The reference colour (in [0, 1], before brightness) that presentedLevel sends to about
// this level: its inverse where it has one.
double linearFromLevel(const GlobalSettings& settings, double level);

// The pixel of the reference an image under these settings shows at (i, j).
inline glm::ivec2 referencePixel(Flip flip, int i, int j, int width, int height) {
    const bool horizontal = flip == Flip::Horizontal || flip == Flip::Both;
    const bool vertical = flip == Flip::Vertical || flip == Flip::Both;
    return {horizontal ? width - 1 - i : i, vertical ? height - 1 - j : j};
}
