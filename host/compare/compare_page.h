// The HTML report of a comparison (compare --report DIR): one self-contained page, its
// images inside it as PNG data, no script or style from the network. It shows the text
// report, the image and the reference under the global settings found, a control that
// flips between the two (a button, or the F key), and the signed difference as a heat
// map (blue where the image is darker, red where it is brighter, grey where it matches).
#pragma once

#include "compare/comparison.h"

#include <filesystem>
#include <string>
#include <vector>

// The page's HTML for one comparison.
std::string comparisonPage(const Comparison& comparison);

// A folder's index page: a row per image, each linking to its own page (PAGE_NAMES[k]
// beside it), and the failures.
std::string folderPage(const std::vector<Comparison>& comparisons,
                       const std::vector<std::string>& pageNames, const std::string& table);

// Levels as the bytes a PNG of them holds: rounded, clamped to 0..255 (NaN to 0), alpha 255.
Image8 shownBytes(const ImageF& levels);

// The heat map: per pixel, grey where it matches; else blue (darker) or red (brighter),
// full at 64 levels of difference or more.
Image8 differenceHeatmap(const PixelMatch& match);
