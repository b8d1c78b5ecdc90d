// Raytracer compare (docs/compare.md): a handed-in image, or a folder of them, against the
// reference of its scene. Reads its own options; main.cpp hands it the arguments after
// the word "compare".
#pragma once

#include <string>
#include <vector>

// The usage text of the compare command (Raytracer compare --help).
std::string compareUsageText();

// Runs the command; returns the exit status (0 when every image was compared, whatever
// the verdicts; 3 when an image or a scene could not be read). Throws UsageError for a
// command line that makes no sense, SceneError for the one scene of a single comparison
// that does not parse, and std::runtime_error for an image that cannot be read or a
// report that cannot be written.
int runCompareCommand(const std::vector<std::string>& arguments);
