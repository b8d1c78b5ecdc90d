// What a comparison says: a short text for people (the verdict, the global differences
// found, the share of matching pixels, where the rest is, worst first) and JSON for
// graders (docs/compare.md has the schema). The HTML page is compare_page.h.
#pragma once

#include "compare/comparison.h"

#include <string>
#include <vector>

// The JSON schema's name and version; the version changes when a field changes meaning or
// goes away (new fields may be added within a version).
inline constexpr const char* kCompareSchema = "raytracer-compare";
inline constexpr int kCompareSchemaVersion = 1;

// The regions the text lists (and diagnoses); the JSON holds kListedRegions (comparison.h).
inline constexpr std::size_t kTextRegions = kDiagnosedRegions;

std::string compareText(const Comparison& comparison);

// The text's lines for region k of the comparison: where it is, what it lies on, its cause
// and, when none explains it, its pixel's ray tree.
std::string regionText(const Comparison& comparison, std::size_t k);

// A pixel's ray tree with the terms the image implies, as the text prints it (indented).
std::string readingText(const RayTreeReading& reading);

// One image of a folder that could not be compared: why.
struct CompareFailure {
    std::string image, scene, message;
};

// The whole report: {"schema", "version", "images": [...]}, one entry a comparison or
// failure, in that order.
std::string compareJson(const std::vector<Comparison>& comparisons,
                        const std::vector<CompareFailure>& failures);

// A folder's table: a line per image (verdict, matching share, global differences as
// options), then the failures.
std::string folderTable(const std::vector<Comparison>& comparisons,
                        const std::vector<CompareFailure>& failures);

// "99.98%": a share as a percentage that says 100% only when it is all, 0% only when none.
std::string percent(double fraction);
