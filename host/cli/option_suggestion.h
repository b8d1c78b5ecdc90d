// "did you mean --width?" for an unknown option: the options --help documents that are a
// near miss of what was typed. Kept apart from options.cpp, which only reads options.
#pragma once

#include <string>
#include <vector>

// Every long option --help names ("--width", "--offset", ...), each once, in its order.
std::vector<std::string> documentedOptions(const std::string& helpText);

// The candidates closest to typed: those one edit away, else those that typed begins, else
// those two edits away; at most three, joined as "--a, --b or --c".
// Empty when none is close or typed is too short ("--" or "--x") to mean anything.
std::string closeOptions(const std::string& typed, const std::vector<std::string>& candidates);
