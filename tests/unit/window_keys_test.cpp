// The window's keys table (host/cli/window_keys.h) is the one description of its keys:
// README.md and docs/window.md hold its markdown between their markers, --help and the
// window's line are made from it, and host/window/input.cpp handles exactly the keys and
// gestures it lists. Reads the sources; no GLFW, no Vulkan.
#include "cli/options.h"
#include "cli/window_keys.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace {

const std::filesystem::path kSourceDir = PROJECT_SOURCE_DIR;

std::string readFile(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    EXPECT_TRUE(file) << "cannot read " << path;
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

TEST(WindowKeys, DocsHoldTheTableBetweenTheirMarkers) {
    const std::string begin = "<!-- window-keys:begin -->\n", end = "<!-- window-keys:end -->";
    for (const char* doc : {"README.md", "docs/window.md"}) {
        const std::string text = readFile(kSourceDir / doc);
        const std::size_t first = text.find(begin), last = text.find(end);
        ASSERT_NE(first, std::string::npos) << doc << " has no " << begin;
        ASSERT_NE(last, std::string::npos) << doc << " has no " << end;
        ASSERT_LT(first, last) << doc;
        EXPECT_EQ(text.find(begin, first + 1), std::string::npos) << doc << ": markers twice";
        EXPECT_EQ(text.substr(first + begin.size(), last - first - begin.size()),
                  windowKeysMarkdown())
            << doc << " between its markers should read (the table in host/cli/window_keys.h):\n"
            << windowKeysMarkdown();
    }
}

TEST(WindowKeys, HelpHoldsTheKeysAndTheWindowLineIsOneLine) {
    const std::string help = usageText(), line = windowKeysLine();
    EXPECT_NE(help.find(windowKeysHelp()), std::string::npos) << help;
    // tests/window/window_test.sh looks for this start of the line on stderr.
    EXPECT_EQ(line.rfind("Window: Esc or Q quits; ", 0), 0u) << line;
    EXPECT_EQ(line.find('\n'), line.size() - 1) << line;
}

// The GLFW names of what the table lists: its keys split at " or " and "/", named as GLFW
// does ("Left Control" is GLFW_KEY_LEFT_CONTROL, "Shift+P" GLFW_KEY_P with GLFW_MOD_SHIFT), and
// the gestures by the input they read.
std::set<std::string> glfwNamesInTable() {
    std::set<std::string> names;
    for (const WindowKey& entry : kWindowKeys) {
        std::string keys(entry.keys);
        keys = std::regex_replace(keys, std::regex(" or "), "/");
        std::stringstream list(keys);
        for (std::string key; std::getline(list, key, '/');) {
            if (key == "left drag")
                names.insert("GLFW_MOUSE_BUTTON_LEFT");
            else if (key == "right drag")
                names.insert("GLFW_MOUSE_BUTTON_RIGHT");
            else if (key.ends_with(" + left click")) { // a key held while clicking
                names.insert("GLFW_MOUSE_BUTTON_LEFT");
                names.insert("GLFW_KEY_" + key.substr(0, key.size() - 13));
            } else if (key == "wheel")
                names.insert("glfwSetScrollCallback");
            else if (key == "Esc")
                names.insert("GLFW_KEY_ESCAPE");
            else if (key.rfind("Shift+", 0) == 0) { // the key, read with the Shift modifier
                names.insert("GLFW_MOD_SHIFT");
                names.insert("GLFW_KEY_" + key.substr(6));
            } else {
                for (char& c : key)
                    c = c == ' ' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
                names.insert("GLFW_KEY_" + key);
            }
        }
    }
    return names;
}

TEST(WindowKeys, TheInputCodeHandlesExactlyTheListedKeys) {
    const std::string input = readFile(kSourceDir / "host/window/input.cpp");
    std::set<std::string> handled;
    const std::regex glfwName(
        "GLFW_KEY_[A-Z0-9_]+|GLFW_MOUSE_BUTTON_[A-Z0-9_]+|GLFW_MOD_SHIFT|glfwSetScrollCallback");
    for (auto it = std::sregex_iterator(input.begin(), input.end(), glfwName);
         it != std::sregex_iterator(); ++it)
        handled.insert(it->str());
    const std::set<std::string> listed = glfwNamesInTable();
    for (const std::string& name : listed)
        EXPECT_TRUE(handled.count(name))
            << "the table lists " << name << ", which host/window/input.cpp does not handle";
    for (const std::string& name : handled)
        EXPECT_TRUE(listed.count(name)) << "host/window/input.cpp handles " << name
                                        << ", which the table in host/cli/window_keys.h omits";
}

// No key or gesture is listed twice: a new binding (I, the pixel story) took no old one.
TEST(WindowKeys, EachKeyIsListedOnce) {
    std::multiset<std::string> names;
    for (const WindowKey& entry : kWindowKeys) {
        std::string keys = std::regex_replace(std::string(entry.keys), std::regex(" or "), "/");
        std::stringstream list(keys);
        for (std::string key; std::getline(list, key, '/');)
            names.insert(key);
    }
    for (const std::string& name : names)
        EXPECT_EQ(names.count(name), 1u) << name << " is bound twice";
    EXPECT_EQ(names.count("I"), 1u);
}

// The I key's pixel: window units scaled to image pixels, floor, nothing outside.
TEST(WindowKeys, PixelUnderCursorMapsWindowUnitsToImagePixels) {
    using P = std::optional<glm::uvec2>;
    EXPECT_EQ(pixelUnderCursor(0.0, 0.0, 640, 480, 640, 480), P(glm::uvec2(0, 0)));
    EXPECT_EQ(pixelUnderCursor(10.7, 20.2, 640, 480, 640, 480), P(glm::uvec2(10, 20)));
    EXPECT_EQ(pixelUnderCursor(639.99, 479.99, 640, 480, 640, 480), P(glm::uvec2(639, 479)));
    // A high-density display: two image pixels per window unit.
    EXPECT_EQ(pixelUnderCursor(100.5, 50.25, 320, 240, 640, 480), P(glm::uvec2(201, 100)));
    // Fewer pixels than units (an image not yet resized to the window).
    EXPECT_EQ(pixelUnderCursor(639.0, 0.0, 640, 480, 320, 240), P(glm::uvec2(319, 0)));
    // Outside the window (GLFW reports the cursor there too while a button is held).
    EXPECT_EQ(pixelUnderCursor(640.0, 10.0, 640, 480, 640, 480), std::nullopt);
    EXPECT_EQ(pixelUnderCursor(10.0, 480.0, 640, 480, 640, 480), std::nullopt);
    EXPECT_EQ(pixelUnderCursor(-0.5, 10.0, 640, 480, 640, 480), std::nullopt);
    EXPECT_EQ(pixelUnderCursor(10.0, -3.0, 640, 480, 640, 480), std::nullopt);
    // A minimised window or an empty image.
    EXPECT_EQ(pixelUnderCursor(0.0, 0.0, 0, 0, 640, 480), std::nullopt);
    EXPECT_EQ(pixelUnderCursor(0.0, 0.0, 640, 480, 0, 480), std::nullopt);
}

} // namespace
