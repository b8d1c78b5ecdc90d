#include "cli/output_pattern.h"

#include <functional>
#include <string_view>

namespace {

// Calls onField for each {field} of pattern, onText for the text between; stops and
// returns the problem at the first field that is not one.
std::string walkPattern(const std::string& pattern,
                        const std::function<void(std::string_view)>& onText,
                        const std::function<void(std::string_view name, int width)>& onField) {
    std::size_t at = 0;
    while (at < pattern.size()) {
        const std::size_t open = pattern.find('{', at);
        onText(std::string_view(pattern).substr(at, open - at));
        if (open == std::string::npos) break;
        const std::size_t close = pattern.find('}', open);
        if (close == std::string::npos) return "a '{' is not closed";
        const std::string field = pattern.substr(open + 1, close - open - 1);
        if (field == "name") {
            onField("name", 0);
        } else if (field == "frame") {
            onField("frame", 0);
        } else if (field.size() == 8 && field.compare(0, 7, "frame:0") == 0 && field[7] >= '1' &&
                   field[7] <= '9') {
            onField("frame", field[7] - '0');
        } else {
            return "unknown field {" + field + "} (known: {name}, {frame}, {frame:04})";
        }
        at = close + 1;
    }
    return "";
}

} // namespace

bool isOutputFolder(const std::filesystem::path& output) {
    const std::string text = output.string();
    std::error_code error;
    return (!text.empty() && text.back() == '/') || std::filesystem::is_directory(output, error);
}

std::filesystem::path folderOutputPattern(const std::filesystem::path& folder, bool frames) {
    return folder / (frames ? "{name}-{frame:04}.png" : "{name}.png");
}

std::string outputPatternProblem(const std::string& pattern) {
    return walkPattern(
        pattern, [](std::string_view) {}, [](std::string_view, int) {});
}

bool outputPatternHas(const std::string& pattern, const std::string& field) {
    bool found = false;
    walkPattern(
        pattern, [](std::string_view) {},
        [&](std::string_view name, int) { found = found || name == field; });
    return found;
}

std::filesystem::path expandOutputPattern(const std::string& pattern, const std::string& name,
                                          std::uint32_t frame) {
    std::string file;
    walkPattern(
        pattern, [&](std::string_view text) { file += text; },
        [&](std::string_view field, int width) {
            if (field == "name") {
                file += name;
                return;
            }
            const std::string digits = std::to_string(frame);
            if (int(digits.size()) < width) file += std::string(width - digits.size(), '0');
            file += digits;
        });
    return file;
}
