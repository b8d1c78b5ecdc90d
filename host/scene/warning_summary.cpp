#include "scene/warning_summary.h"

#include <cctype>
#include <map>

namespace {

constexpr const char* kMarker = ": warning: ";

// 34985 as "34,985".
std::string withThousands(std::size_t count) {
    std::string digits = std::to_string(count), text;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) text += ',';
        text += digits[i];
    }
    return text;
}

bool isDigit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// "input.scene" of "input.scene:17: warning: ...": the location without its line.
std::string fileOf(const std::string& warning) {
    const std::string location = warning.substr(0, warning.find(kMarker));
    const std::size_t colon = location.rfind(':');
    return colon == std::string::npos ? location : location.substr(0, colon);
}

} // namespace

std::string warningKind(const std::string& warning) {
    const std::size_t marker = warning.find(kMarker);
    const std::string message = marker == std::string::npos
                                    ? warning
                                    : warning.substr(marker + std::string(kMarker).size());
    std::string kind;
    for (std::size_t i = 0; i < message.size();) {
        // A number: digits (after a sign or a point too) and what continues it (1.5e-3).
        const bool starts =
            isDigit(message[i]) || ((message[i] == '-' || message[i] == '+' || message[i] == '.') &&
                                    i + 1 < message.size() && isDigit(message[i + 1]));
        if (starts && (i == 0 || !std::isalpha(static_cast<unsigned char>(message[i - 1])))) {
            ++i;
            while (i < message.size() && (isDigit(message[i]) || message[i] == '.' ||
                                          message[i] == 'e' || message[i] == 'E' ||
                                          ((message[i] == '-' || message[i] == '+') &&
                                           (message[i - 1] == 'e' || message[i - 1] == 'E'))))
                ++i;
            // "1." ending a sentence keeps its full stop.
            if (message[i - 1] == '.' && i >= 2 && isDigit(message[i - 2])) --i;
            kind += 'N';
        } else {
            kind += message[i++];
        }
    }
    return kind;
}

std::vector<std::string> summarisedWarnings(const std::vector<std::string>& warnings,
                                            std::size_t perKind) {
    struct Tally {
        std::size_t seen = 0;
        std::string file;
    };
    std::map<std::string, Tally> tallies;
    std::vector<std::string> kindsInOrder, lines;
    for (const std::string& warning : warnings) {
        const std::string kind = warningKind(warning);
        Tally& tally = tallies[kind];
        if (tally.seen++ == 0) {
            tally.file = fileOf(warning);
            kindsInOrder.push_back(kind);
        }
        if (tally.seen <= perKind) lines.push_back(warning);
    }
    for (const std::string& kind : kindsInOrder) {
        const Tally& tally = tallies[kind];
        if (tally.seen > perKind)
            lines.push_back(tally.file + kMarker + "... and " +
                            withThousands(tally.seen - perKind) + " more warnings that " + kind);
    }
    return lines;
}
