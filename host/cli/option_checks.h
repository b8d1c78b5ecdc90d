// The checks that need the whole command line: options that cannot go together, values
// that must fit the image, and a batch's -o (a pattern or a folder, which becomes its
// pattern). Each refusal is a UsageError saying what to give instead.
#pragma once

#include "cli/options.h"

#include <string>
#include <vector>

// What the command line said beyond the values in Options.
struct OptionsGiven {
    bool jpegQuality = false;           // --quality (any value names a JPEG output)
    std::vector<std::string> modelOnly; // --up, --crease, --no-ground, ..., in the order given
    bool view = false;                  // --view
};

void checkOptionCombinations(Options& options, const OptionsGiven& given);
