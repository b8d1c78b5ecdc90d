#include "compare/global_settings.h"

#include "reference/reference_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

std::string channelOrderName(const std::array<int, 3>& channels) {
    std::string name;
    for (int c : channels)
        name += "rgb"[c];
    return name;
}

bool channelOrderFromName(const std::string& name, std::array<int, 3>& channels) {
    if (name.size() != 3) return false;
    std::array<int, 3> order{};
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t at = std::string("rgb").find(name[k]);
        if (at == std::string::npos) return false;
        order[k] = int(at);
    }
    if (order[0] == order[1] || order[1] == order[2] || order[0] == order[2]) return false;
    channels = order;
    return true;
}

const char* flipName(Flip flip) {
    switch (flip) {
    case Flip::None:
        return "none";
    case Flip::Vertical:
        return "vertical";
    case Flip::Horizontal:
        return "horizontal";
    case Flip::Both:
        return "both";
    }
    return "none";
}

const char* fovAxisName(FovAxis axis) {
    return axis == FovAxis::Vertical ? "vertical" : "horizontal";
}

const char* rayPositionName(RayPosition rays) {
    return rays == RayPosition::Centre ? "centre" : "corner";
}

const char* quantizeName(Quantize quantize) {
    return quantize == Quantize::Round ? "round" : "truncate";
}

namespace {

const GlobalSettings kDefaults;

bool sameBackground(const GlobalSettings& settings) {
    return settings.background == kDefaults.background;
}

} // namespace

int departures(const GlobalSettings& s) {
    return int(s.depth != kDefaults.depth) + int(!sameBackground(s)) +
           int(s.fovDegrees != kDefaults.fovDegrees) + int(s.fovAxis != kDefaults.fovAxis) +
           int(s.rays != kDefaults.rays) + int(s.flip != kDefaults.flip) +
           int(s.gamma != kDefaults.gamma) + int(s.channels != kDefaults.channels) +
           int(s.brightness != kDefaults.brightness) + int(s.quantize != kDefaults.quantize);
}

std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", value);
    std::string out = text;
    while (out.back() == '0')
        out.pop_back();
    if (out.back() == '.') out.pop_back();
    return out == "-0" ? "0" : out;
}

std::string departureOptions(const GlobalSettings& s) {
    std::string out;
    auto add = [&](const std::string& option) { out += (out.empty() ? "" : " ") + option; };
    if (s.depth != kDefaults.depth) add("--depth " + std::to_string(s.depth));
    if (!sameBackground(s))
        add("--background " + shortNumber(s.background.x) + "," + shortNumber(s.background.y) +
            "," + shortNumber(s.background.z));
    if (s.fovDegrees != kDefaults.fovDegrees) add("--fov " + shortNumber(s.fovDegrees));
    if (s.fovAxis != kDefaults.fovAxis) add(std::string("--fov-axis ") + fovAxisName(s.fovAxis));
    if (s.rays != kDefaults.rays) add(std::string("--rays ") + rayPositionName(s.rays));
    if (s.flip != kDefaults.flip) add(std::string("--flip ") + flipName(s.flip));
    if (s.gamma != kDefaults.gamma) add("--gamma " + shortNumber(s.gamma));
    if (s.channels != kDefaults.channels) add("--channels " + channelOrderName(s.channels));
    if (s.brightness != kDefaults.brightness) add("--brightness " + shortNumber(s.brightness));
    if (s.quantize != kDefaults.quantize)
        add(std::string("--quantize ") + quantizeName(s.quantize));
    return out;
}

std::string departureWords(const GlobalSettings& s) {
    std::string out;
    auto add = [&](const std::string& phrase) { out += (out.empty() ? "" : "; ") + phrase; };
    if (s.depth != kDefaults.depth)
        add(s.depth == 0   ? "no reflections (depth 0)"
            : s.depth == 1 ? "1 reflection bounce"
                           : std::to_string(s.depth) + " reflection bounces");
    if (!sameBackground(s))
        add("background " + shortNumber(s.background.x) + "," + shortNumber(s.background.y) + "," +
            shortNumber(s.background.z));
    if (s.fovDegrees != kDefaults.fovDegrees)
        add("a field of view of " + shortNumber(s.fovDegrees) + " degrees");
    if (s.fovAxis == FovAxis::Horizontal) add("the field of view spans the width, not the height");
    if (s.rays == RayPosition::Corner) add("rays through pixel corners, not centres");
    if (s.flip == Flip::Vertical) add("upside down (rows in reverse order)");
    if (s.flip == Flip::Horizontal) add("mirrored left to right");
    if (s.flip == Flip::Both) add("rotated half a turn");
    if (s.gamma != kDefaults.gamma) add("gamma " + shortNumber(s.gamma) + " applied");
    if (s.channels != kDefaults.channels)
        add("channels in " + channelOrderName(s.channels) + " order");
    if (s.brightness != kDefaults.brightness) add("brightness times " + shortNumber(s.brightness));
    if (s.quantize == Quantize::Truncate) add("bytes truncated, not rounded");
    return out;
}

ReferenceSettings referenceSettingsFor(const GlobalSettings& settings, int width, int height) {
    ReferenceSettings reference;
    reference.width = width;
    reference.height = height;
    reference.depth = settings.depth;
    reference.background = settings.background;
    reference.fovDegrees = settings.fovDegrees;
    if (settings.fovAxis == FovAxis::Horizontal) {
        // The same tangent across the width: the vertical angle that gives it.
        const double halfWidth = std::tan(settings.fovDegrees * std::numbers::pi / 360.0);
        reference.fovDegrees = std::atan(halfWidth * height / width) * 360.0 / std::numbers::pi;
    }
    reference.cornerRays = settings.rays == RayPosition::Corner;
    return reference;
}

double presentedLevel(const GlobalSettings& settings, double c) {
    const double scaled = c * settings.brightness;
    double v = scaled > 0 ? std::min(scaled, 1.0) : 0.0; // also sends NaN to 0
    if (settings.gamma != 1.0) v = std::pow(v, 1.0 / settings.gamma);
    return std::floor(v * 255.0 + (settings.quantize == Quantize::Round ? 0.5 : 0.0));
}

double linearFromLevel(const GlobalSettings& settings, double level) {
    const double centre = settings.quantize == Quantize::Round ? level : level + 0.5;
    double v = std::clamp(centre / 255.0, 0.0, 1.0);
    if (settings.gamma != 1.0) v = std::pow(v, settings.gamma);
    return v / settings.brightness;
}
