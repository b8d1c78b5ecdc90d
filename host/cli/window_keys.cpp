#include "cli/window_keys.h"

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
