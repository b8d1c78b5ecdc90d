// The checks that need the whole command line: options that cannot go together, values
// that must fit the image, and a batch's -o (a pattern or a folder, which becomes its
// pattern). Each refusal is a UsageError saying what to give instead.
#pragma once

#include "cli/options.h"

// jpegQualityGiven: --quality was given (any value names a JPEG output).
void checkOptionCombinations(Options& options, bool jpegQualityGiven);
