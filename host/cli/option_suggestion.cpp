#include "cli/option_suggestion.h"

#include <algorithm>
#include <cctype>

namespace {

// Levenshtein distance: insertions, deletions and substitutions, one each.
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1,
                                   previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::string joined(const std::vector<std::string>& words) {
    std::string text;
    for (std::size_t i = 0; i < words.size(); ++i)
        text += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
    return text;
}

} // namespace

std::vector<std::string> documentedOptions(const std::string& helpText) {
    std::vector<std::string> options;
    for (std::size_t at = helpText.find("--"); at != std::string::npos;
         at = helpText.find("--", at + 2)) {
        std::size_t end = at + 2;
        while (end < helpText.size() &&
               (std::islower(static_cast<unsigned char>(helpText[end])) || helpText[end] == '-'))
            ++end;
        const std::string option = helpText.substr(at, end - at);
        if (option.size() > 3 && std::find(options.begin(), options.end(), option) == options.end())
            options.push_back(option);
        at = end - 2;
    }
    return options;
}

std::string closeOptions(const std::string& typed, const std::vector<std::string>& candidates) {
    if (typed.size() < 4 || typed.compare(0, 2, "--") != 0) return "";
    std::size_t best = 3;
    std::vector<std::string> nearest, extending;
    for (const std::string& candidate : candidates) {
        const std::size_t distance = editDistance(typed, candidate);
        if (distance <= 2 && distance < best) {
            best = distance;
            nearest.clear();
        }
        if (distance <= 2 && distance == best) nearest.push_back(candidate);
        if (candidate.compare(0, typed.size(), typed) == 0) extending.push_back(candidate);
    }
    // One edit away is a typo; otherwise an option that begins with what was typed is the
    // likelier meaning ("--dump" is --dump-shaders cut short, not --up two edits away).
    const bool typo = !nearest.empty() && best <= 1;
    std::vector<std::string>& chosen = typo || extending.empty() ? nearest : extending;
    if (chosen.size() > 3) chosen.resize(3);
    return joined(chosen);
}
