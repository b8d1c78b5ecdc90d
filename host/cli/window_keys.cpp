#include "cli/window_keys.h"

#include <cmath>

namespace {

std::string sentence(const WindowKey& key) {
    return std::string(key.keys) + " " + std::string(key.effect);
}

} // namespace

std::string windowKeysHelp() {
    std::string text = "Window keys and mouse:\n";
    for (const WindowKey& key : kWindowKeys)
        text += "  " + sentence(key) + "\n";
    return text;
}

std::string windowKeysLine() {
    std::string line = "Window:";
    for (std::size_t i = 0; i < kWindowKeys.size(); ++i)
        line += (i == 0 ? " " : "; ") + sentence(kWindowKeys[i]);
    return line + ".\n";
}

std::string windowKeysMarkdown() {
    std::string table = "| key or gesture | effect |\n|---|---|\n";
    for (const WindowKey& key : kWindowKeys) {
        std::string effect(key.effect);
        if (!key.detail.empty()) effect += " " + std::string(key.detail);
        table += "| " + std::string(key.keys) + " | " + effect + " |\n";
    }
    return table;
}

std::optional<glm::uvec2> pixelUnderCursor(double cursorX, double cursorY, int windowWidth,
                                           int windowHeight, std::uint32_t imageWidth,
                                           std::uint32_t imageHeight) {
    if (windowWidth <= 0 || windowHeight <= 0 || imageWidth == 0 || imageHeight == 0)
        return std::nullopt;
    // Pixel k covers [k, k + 1) image units; GLFW reports the cursor in window units.
    const double x = std::floor(cursorX * double(imageWidth) / double(windowWidth));
    const double y = std::floor(cursorY * double(imageHeight) / double(windowHeight));
    if (!(x >= 0 && y >= 0 && x < double(imageWidth) && y < double(imageHeight)))
        return std::nullopt;
    return glm::uvec2(std::uint32_t(x), std::uint32_t(y));
}
