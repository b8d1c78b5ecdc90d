#include "compare/compare_report.h"

#include "base/json.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

std::string fixed(double value, int decimals) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

std::string levelsText(double levels) {
    return shortNumber(levels) + "/255";
}

std::string verdictLine(const Comparison& c) {
    switch (c.verdict) {
    case Verdict::Matches:
        return "matches";
    case Verdict::MatchesWithGlobalSettings:
        return "matches once its global differences are applied";
    case Verdict::Differs:
        break;
    }
    return "differs";
}

// "the sphere of line 9 (80%), the triangle of line 30 (20%); in shadow 60%": what the
// region's traced pixels lie on, the three largest shares.
std::string factsText(const RegionFacts& f) {
    if (f.traced == 0) return "";
    auto share = [&](long n) {
        return std::to_string(int(std::lround(100.0 * double(n) / double(f.traced)))) + "%";
    };
    // The objects and the background, the most pixels first.
    std::vector<std::pair<long, std::string>> parts;
    for (const RegionObject& o : f.objects)
        parts.emplace_back(o.pixels, std::string("the ") + o.primitive.kind + " of line " +
                                         std::to_string(o.primitive.line));
    if (f.background > 0) parts.emplace_back(f.background, "the background");
    std::stable_sort(parts.begin(), parts.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::string out = "on ";
    for (std::size_t k = 0; k < std::min<std::size_t>(3, parts.size()); ++k)
        out += std::string(k ? ", " : "") + parts[k].second + " (" + share(parts[k].first) + ")";
    if (parts.size() > 3) out += " and " + std::to_string(parts.size() - 3) + " more";
    if (f.inShadow > 0) out += "; in shadow " + share(f.inShadow);
    if (f.onMirror > 0) out += "; on mirrors " + share(f.onMirror);
    return out;
}

// "cause: no shadows: ... (95% of its pixels match with it, 0% without)", or that no
// mistake of the catalogue explains it, with the closest.
std::string diagnosisText(const RegionDiagnosis& d) {
    auto share = [](double s) { return std::to_string(int(std::lround(100.0 * s))) + "%"; };
    if (d.cause)
        return std::string("cause: ") + d.cause->mistake->words + " (" + share(d.cause->share) +
               " of its pixels match with this mistake, " + share(d.referenceShare) + " without)";
    if (d.referenceShare >= kExplainingShare)
        return "cause: none needed: within " + levelsText(d.closeness) +
               " the reference itself matches " + share(d.referenceShare) +
               " of its pixels (compression or edge noise)";
    std::string out = "cause: not explained by any known mistake";
    if (!d.trials.empty())
        out += std::string(" (the closest, ") + d.trials.front().mistake->name + ", matches " +
               share(d.trials.front().share) + " of its pixels)";
    return out;
}

std::string colourText(glm::dvec3 c) {
    // Rounding leaves a term that is nothing at -0.000: it is written 0.000.
    auto value = [](double v) { return fixed(std::abs(v) < 5e-4 ? 0.0 : v, 3); };
    return value(c.x) + " " + value(c.y) + " " + value(c.z);
}

std::string readingJson(const RayTreeReading& r) {
    std::string terms;
    for (std::size_t k = 0; k < r.terms.size(); ++k)
        terms += std::string(k ? ", " : "") + "{\"term\": " + jsonString(r.terms[k].name) +
                 ", \"reference\": " + jsonTriple(r.terms[k].reference, 6) +
                 ", \"weight\": " + jsonTriple(r.terms[k].weight, 6) +
                 ", \"implied\": " + jsonTriple(r.terms[k].implied, 6) + "}";
    return ", \"ray_tree\": {\"x\": " + std::to_string(r.pixel.x) +
           ", \"y\": " + std::to_string(r.pixel.y) + ", \"image\": " + jsonTriple(r.image, 6) +
           ", \"reference\": " + jsonTriple(r.reference, 6) +
           ", \"meets\": " + jsonString(r.meets) + ", \"terms\": [" + terms + "]}";
}

// The diagnosis as JSON fields (a leading comma): the cause (null when none explains it),
// the reference's share and every mistake's.
std::string diagnosisJson(const RegionDiagnosis& d) {
    std::string trials;
    for (std::size_t k = 0; k < d.trials.size(); ++k)
        trials += std::string(k ? ", " : "") +
                  "{\"mistake\": " + jsonString(d.trials[k].mistake->name) +
                  ", \"matching_fraction\": " + jsonNumber(d.trials[k].share, 4) + "}";
    return ", \"cause\": " + (d.cause ? jsonString(d.cause->mistake->name) : std::string("null")) +
           ", \"cause_words\": " +
           (d.cause ? jsonString(d.cause->mistake->words) : std::string("null")) +
           ", \"diagnosed_pixels\": " + std::to_string(d.traced) +
           ", \"reference_matching_fraction\": " + jsonNumber(d.referenceShare, 4) +
           ", \"mistakes\": [" + trials + "]";
}

// The region's facts as JSON fields (a leading comma): the traced pixels, the objects and
// the shares in shadow, on mirrors and on the background.
std::string factsJson(const RegionFacts& f) {
    std::string objects;
    for (std::size_t k = 0; k < f.objects.size(); ++k)
        objects += std::string(k ? ", " : "") +
                   "{\"kind\": " + jsonString(f.objects[k].primitive.kind) +
                   ", \"index\": " + std::to_string(f.objects[k].primitive.index) +
                   ", \"line\": " + std::to_string(f.objects[k].primitive.line) +
                   ", \"pixels\": " + std::to_string(f.objects[k].pixels) + "}";
    return ", \"traced_pixels\": " + std::to_string(f.traced) + ", \"objects\": [" + objects +
           "], \"background_pixels\": " + std::to_string(f.background) +
           ", \"in_shadow_pixels\": " + std::to_string(f.inShadow) +
           ", \"on_mirror_pixels\": " + std::to_string(f.onMirror);
}

std::string regionLine(const MismatchRegion& r) {
    const double mean = r.meanSignedDifference;
    const std::string direction = std::abs(mean) < 0.5 ? "both darker and brighter"
                                  : mean < 0 ? "darker by " + levelsText(std::round(-mean))
                                             : "brighter by " + levelsText(std::round(mean));
    return std::to_string(r.pixels) + (r.pixels == 1 ? " pixel" : " pixels") + " in x " +
           std::to_string(r.left) + "-" + std::to_string(r.right) + ", y " + std::to_string(r.top) +
           "-" + std::to_string(r.bottom) + ": " + direction +
           (std::abs(mean) < 0.5 ? "" : " on average");
}

std::string settingsJson(const GlobalSettings& s) {
    return "{\"depth\": " + std::to_string(s.depth) +
           ", \"background\": " + jsonTriple(s.background, 6) +
           ", \"fov\": " + jsonNumber(s.fovDegrees, 6) +
           ", \"fov_axis\": " + jsonString(fovAxisName(s.fovAxis)) +
           ", \"rays\": " + jsonString(rayPositionName(s.rays)) +
           ", \"flip\": " + jsonString(flipName(s.flip)) +
           ", \"gamma\": " + jsonNumber(s.gamma, 6) +
           ", \"channels\": " + jsonString(channelOrderName(s.channels)) +
           ", \"brightness\": " + jsonNumber(s.brightness, 6) +
           ", \"quantize\": " + jsonString(quantizeName(s.quantize)) + "}";
}

std::string comparisonJson(const Comparison& c) {
    const PixelMatch& m = c.match;
    std::string regions;
    for (std::size_t k = 0; k < std::min(kListedRegions, m.regions.size()); ++k) {
        const MismatchRegion& r = m.regions[k];
        regions +=
            std::string(k ? ", " : "") + "{\"left\": " + std::to_string(r.left) +
            ", \"top\": " + std::to_string(r.top) + ", \"right\": " + std::to_string(r.right) +
            ", \"bottom\": " + std::to_string(r.bottom) +
            ", \"pixels\": " + std::to_string(r.pixels) +
            ", \"mean_signed_difference\": " + jsonNumber(r.meanSignedDifference, 4) +
            (k < c.regionFacts.size() ? factsJson(c.regionFacts[k]) : std::string()) +
            (k < c.diagnoses.size() ? diagnosisJson(c.diagnoses[k]) : std::string()) +
            (k < c.readings.size() && c.readings[k] ? readingJson(*c.readings[k]) : std::string()) +
            "}";
    }
    const SearchResult& s = c.search;
    return "{\"image\": " + jsonString(c.imagePath.string()) +
           ", \"scene\": " + jsonString(c.scenePath.string()) +
           ", \"format\": " + jsonString(formatName(c.image.format)) + ", \"jpeg_quality\": " +
           (c.image.jpegQuality ? std::to_string(*c.image.jpegQuality) : "null") +
           ", \"width\": " + std::to_string(m.width) + ", \"height\": " + std::to_string(m.height) +
           ", \"verdict\": " + jsonString(verdictName(c.verdict)) +
           ", \"tolerance\": " + jsonNumber(c.tolerance.levels, 6) +
           ", \"tolerance_reason\": " + jsonString(c.tolerance.reason) +
           ", \"matching_fraction\": " + jsonNumber(m.fractionMatching, 6) +
           ", \"pixels\": " + std::to_string(m.pixels) +
           ", \"matching_pixels\": " + std::to_string(m.matching) +
           ", \"mean_absolute_difference\": " + jsonNumber(m.meanAbsoluteDifference, 4) +
           ", \"settings\": " + settingsJson(c.settings) +
           ", \"options\": " + jsonString(departureOptions(c.settings)) +
           ", \"differences\": " + jsonString(departureWords(c.settings)) +
           ", \"as_given_matching_fraction\": " + jsonNumber(c.asGivenFraction, 6) +
           ", \"unconvincing\": " +
           (c.unconvincing.empty()
                ? std::string("null")
                : "{\"options\": " + jsonString(c.unconvincing) +
                      ", \"matching_fraction\": " + jsonNumber(c.unconvincingFraction, 6) + "}") +
           ", \"set_aside_for_mistake\": " +
           (!c.mistakeOverSettings
                ? std::string("null")
                : "{\"options\": " + jsonString(c.setAside) +
                      ", \"options_sample_fraction\": " + jsonNumber(s.close, 6) +
                      ", \"mistake\": " + jsonString(c.mistakeOverSettings->mistake->name) +
                      ", \"mistake_sample_fraction\": " +
                      jsonNumber(c.mistakeOverSettings->share, 6) + "}") +
           ", \"search\": {\"candidates\": " + std::to_string(s.candidates) +
           ", \"sample_pixels\": " + std::to_string(s.samplePixels) +
           ", \"rays\": " + std::to_string(s.tracedRays) +
           ", \"seconds\": " + jsonNumber(s.seconds) + "}" +
           ", \"reference_seconds\": " + jsonNumber(c.renderSeconds) +
           ", \"diagnosis_seconds\": " + jsonNumber(c.diagnosisSeconds) +
           ", \"seconds\": " + jsonNumber(c.seconds) +
           ", \"regions_total\": " + std::to_string(m.regions.size()) + ", \"regions\": [" +
           regions + "]}";
}

} // namespace

// The representative pixel's ray tree, a line a term, indented under its region.
std::string readingText(const RayTreeReading& r) {
    std::string out = "     pixel (" + std::to_string(r.pixel.x) + ", " +
                      std::to_string(r.pixel.y) + "): the image " + colourText(r.image) +
                      ", the reference " + colourText(r.reference) + "; the eye ray meets " +
                      r.meets + "\n";
    if (r.terms.empty()) return out;
    out += "       its terms in the reference, and what the image implies were each the only one "
           "that differs:\n";
    std::size_t width = 0;
    for (const ImpliedTerm& t : r.terms)
        width = std::max(width, t.name.size());
    for (const ImpliedTerm& t : r.terms) {
        std::string name = t.name;
        name.resize(width, ' ');
        out += "         " + name + "  " + colourText(t.reference) + "  implies " +
               colourText(t.implied) + "\n";
    }
    return out;
}

std::string percent(double fraction) {
    std::string text = fixed(fraction * 100.0, 2);
    if (text == "100.00" && fraction < 1) text = "99.99";
    if (text == "0.00" && fraction > 0) text = "0.01";
    return text + "%";
}

std::string regionText(const Comparison& c, std::size_t k) {
    std::string out = "  " + std::to_string(k + 1) + ". " + regionLine(c.match.regions[k]) + "\n";
    if (k < c.regionFacts.size() && c.regionFacts[k].traced > 0)
        out += "     " + factsText(c.regionFacts[k]) + "\n";
    if (k < c.diagnoses.size() && c.diagnoses[k].traced > 0)
        out += "     " + diagnosisText(c.diagnoses[k]) + "\n";
    if (k < c.readings.size() && c.readings[k]) out += readingText(*c.readings[k]);
    return out;
}

std::string compareText(const Comparison& c) {
    const PixelMatch& m = c.match;
    const SearchResult& s = c.search;
    std::string out = c.imagePath.string() + " (" + formatName(c.image.format) + ", " +
                      std::to_string(m.width) + "x" + std::to_string(m.height) + ") against " +
                      c.scenePath.string() + "\n";
    out += "verdict: " + verdictLine(c) + ": " + percent(m.fractionMatching) +
           " of pixels within " + levelsText(c.tolerance.levels) + " (" + c.tolerance.reason +
           "; a pixel also matches its neighbours' reference)\n";
    const std::string options = departureOptions(c.settings);
    if (options.empty()) {
        out += "global differences: none found\n";
    } else {
        out += "global differences: " + departureWords(c.settings) + "\n";
        out += "  your image matches the reference with `" + options + "` on " +
               percent(m.fractionMatching) + " of pixels within " + levelsText(c.tolerance.levels) +
               "; as given, on " + percent(c.asGivenFraction) + "\n";
    }
    if (c.mistakeOverSettings)
        out += "  (`" + c.setAside + "` brings " + percent(s.close) +
               " of sampled pixels close, but as given a tracer with a classic mistake brings " +
               percent(c.mistakeOverSettings->share) + ", " +
               c.mistakeOverSettings->mistake->words + ": see the regions)\n";
    if (!c.unconvincing.empty())
        out += "  (the closest, `" + c.unconvincing + "`, reaches " +
               percent(c.unconvincingFraction) + ": too little to explain the differences)\n";
    out += "search: " + std::to_string(s.candidates) + " settings on " +
           std::to_string(s.samplePixels) + " sampled pixels (" + std::to_string(s.tracedRays) +
           " eye rays) in " + fixed(s.seconds, 2) + " s; the full reference in " +
           fixed(c.renderSeconds, 2) + " s; the regions' causes in " +
           fixed(c.diagnosisSeconds, 2) + " s\n";
    if (!m.regions.empty()) {
        out += "where the rest is (worst first):\n";
        long listed = 0;
        for (std::size_t k = 0; k < std::min(kTextRegions, m.regions.size()); ++k) {
            out += regionText(c, k);
            listed += m.regions[k].pixels;
        }
        if (m.regions.size() > kTextRegions)
            out += "  and " + std::to_string(m.regions.size() - kTextRegions) +
                   " more regions of " + std::to_string(m.pixels - m.matching - listed) +
                   " pixels in all\n";
    }
    return out;
}

std::string compareJson(const std::vector<Comparison>& comparisons,
                        const std::vector<CompareFailure>& failures) {
    std::string out = "{\"schema\": " + jsonString(kCompareSchema) +
                      ", \"version\": " + std::to_string(kCompareSchemaVersion) + ", \"images\": [";
    bool first = true;
    for (const Comparison& c : comparisons) {
        out += (first ? "\n  " : ",\n  ") + comparisonJson(c);
        first = false;
    }
    for (const CompareFailure& f : failures) {
        out += (first ? "\n  " : ",\n  ") + std::string("{\"image\": ") + jsonString(f.image) +
               ", \"scene\": " + jsonString(f.scene) +
               ", \"verdict\": \"error\", \"error\": " + jsonString(f.message) + "}";
        first = false;
    }
    return out + "\n]}\n";
}

std::string folderTable(const std::vector<Comparison>& comparisons,
                        const std::vector<CompareFailure>& failures) {
    std::size_t nameWidth = 5;
    for (const Comparison& c : comparisons)
        nameWidth = std::max(nameWidth, c.imagePath.filename().string().size());
    for (const CompareFailure& f : failures)
        nameWidth = std::max(nameWidth, std::filesystem::path(f.image).filename().string().size());
    auto pad = [](std::string text, std::size_t width) {
        text.resize(std::max(width, text.size()), ' ');
        return text;
    };
    std::string out = pad("image", nameWidth) + "  " + pad("verdict", 31) + "  " +
                      pad("matching", 8) + "  global differences\n";
    for (const Comparison& c : comparisons) {
        const std::string options = departureOptions(c.settings);
        out += pad(c.imagePath.filename().string(), nameWidth) + "  " +
               pad(verdictName(c.verdict), 31) + "  " + pad(percent(c.match.fractionMatching), 8) +
               "  " + (options.empty() ? "none" : options) + "\n";
    }
    for (const CompareFailure& f : failures)
        out += pad(std::filesystem::path(f.image).filename().string(), nameWidth) + "  " +
               pad("error", 31) + "  " + pad("-", 8) + "  " + f.message + "\n";
    return out;
}
