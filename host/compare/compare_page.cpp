#include "compare/compare_page.h"

#include "base/json.h"
#include "compare/compare_report.h"

#include <algorithm>
#include <cmath>

namespace {

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* alphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t k = 0; k < bytes.size(); k += 3) {
        const unsigned a = bytes[k], b = k + 1 < bytes.size() ? bytes[k + 1] : 0,
                       c = k + 2 < bytes.size() ? bytes[k + 2] : 0;
        const unsigned triple = (a << 16) | (b << 8) | c;
        out += alphabet[(triple >> 18) & 63];
        out += alphabet[(triple >> 12) & 63];
        out += k + 1 < bytes.size() ? alphabet[(triple >> 6) & 63] : '=';
        out += k + 2 < bytes.size() ? alphabet[triple & 63] : '=';
    }
    return out;
}

std::string escapeHtml(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string pngData(const Image8& image) {
    return "data:image/png;base64," + base64(encodePng("the report's image", image));
}

constexpr const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 1.5em; background: #fafafa; color: #222; }
pre { background: #fff; border: 1px solid #ccc; padding: 0.8em; white-space: pre-wrap; }
.images { display: flex; flex-wrap: wrap; gap: 1.5em; }
figure { margin: 0; flex: 1 1 40%; max-width: 640px; }
figcaption { margin-top: 0.3em; }
img { image-rendering: pixelated; border: 1px solid #888; width: 100%; height: auto; }
button { font-size: 1em; padding: 0.3em 0.8em; }
.heat { position: relative; line-height: 0; }
.region { position: absolute; box-sizing: border-box; border: 2px solid #e8a000; min-width: 6px;
          min-height: 6px; }
.region span { position: absolute; left: -2px; top: -1.4em; line-height: 1.2em;
               background: #e8a000; color: #000; font-size: 12px; padding: 0 0.3em; }
table { border-collapse: collapse; }
td, th { border: 1px solid #ccc; padding: 0.3em 0.6em; text-align: left; }
</style>)";

// The flip control: the button (or F) shows the other image; the page marks itself ready
// once the script has run, which the tests read.
constexpr const char* kFlipScript = R"(<script>
"use strict";
(function () {
  const shown = document.getElementById("flip-image");
  const label = document.getElementById("flip-label");
  const button = document.getElementById("flip-button");
  const sources = { yours: shown.dataset.yours, reference: shown.dataset.reference };
  let showing = "yours";
  function flip() {
    showing = showing === "yours" ? "reference" : "yours";
    shown.src = sources[showing];
    label.textContent = showing === "yours" ? "your image" : "the reference";
  }
  button.addEventListener("click", flip);
  document.addEventListener("keydown", function (event) {
    if (event.key === "f" || event.key === "F") flip();
  });
  document.body.dataset.ready = "yes";
})();
</script>)";

// The regions the text lists, as numbered boxes over the heat map: placed in percent of
// the image, so they stay on their pixels at any displayed size.
std::string regionOutlines(const PixelMatch& match) {
    std::string boxes;
    auto percentOf = [](double value, int size) { return jsonNumber(100.0 * value / size, 6); };
    for (std::size_t k = 0; k < std::min(kTextRegions, match.regions.size()); ++k) {
        const MismatchRegion& r = match.regions[k];
        boxes += "<div class=\"region\" style=\"left:" + percentOf(r.left, match.width) +
                 "%;top:" + percentOf(r.top, match.height) +
                 "%;width:" + percentOf(r.right - r.left + 1, match.width) +
                 "%;height:" + percentOf(r.bottom - r.top + 1, match.height) + "%\"><span>" +
                 std::to_string(k + 1) + "</span></div>\n";
    }
    return boxes;
}

} // namespace

Image8 shownBytes(const ImageF& levels) {
    Image8 image;
    image.width = levels.width;
    image.height = levels.height;
    image.rgba.reserve(levels.rgb.size() / 3 * 4);
    for (std::size_t p = 0; p < levels.rgb.size(); p += 3) {
        for (std::size_t k = 0; k < 3; ++k) {
            const float level = levels.rgb[p + k]; // a float file's may be NaN or beyond 255
            image.rgba.push_back(level > 0 ? std::uint8_t(std::lround(std::min(level, 255.0f)))
                                           : 0);
        }
        image.rgba.push_back(255);
    }
    return image;
}

Image8 differenceHeatmap(const PixelMatch& match) {
    Image8 image;
    image.width = match.width;
    image.height = match.height;
    image.rgba.resize(std::size_t(match.width) * std::size_t(match.height) * 4);
    for (std::size_t p = 0; p < match.matches.size(); ++p) {
        std::uint8_t* out = &image.rgba[4 * p];
        out[3] = 255;
        if (match.matches[p]) {
            out[0] = out[1] = out[2] = 200;
            continue;
        }
        const double d = match.signedDifference[p];
        const double strength = std::min(1.0, std::abs(d) / 64.0);
        const auto fade = std::uint8_t(std::lround(200.0 * (1.0 - strength)));
        const auto full = std::uint8_t(std::lround(200.0 + 55.0 * strength));
        if (d < 0) { // darker: blue
            out[0] = fade;
            out[1] = fade;
            out[2] = full;
        } else { // brighter (or different in hue at the same brightness): red
            out[0] = full;
            out[1] = fade;
            out[2] = fade;
        }
    }
    return image;
}

std::string comparisonPage(const Comparison& c) {
    const std::string yours = pngData(shownBytes(c.image.levels));
    const std::string reference = pngData(shownBytes(c.expected));
    const std::string title = "compare: " + c.imagePath.filename().string();
    std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                       "<title>" +
                       escapeHtml(title) + "</title>\n" + kStyle + "\n</head>\n<body>\n";
    page += "<h1>" + escapeHtml(c.imagePath.filename().string()) + " against " +
            escapeHtml(c.scenePath.filename().string()) + "</h1>\n";
    page += "<pre id=\"report\">" + escapeHtml(compareText(c)) + "</pre>\n";
    page += "<div class=\"images\">\n<figure>\n<img id=\"flip-image\" alt=\"your image or the "
            "reference\" src=\"" +
            yours + "\" data-yours=\"" + yours + "\" data-reference=\"" + reference +
            "\">\n<figcaption><button id=\"flip-button\" "
            "type=\"button\">Flip</button> (or F) showing <span id=\"flip-label\">your "
            "image</span></figcaption>\n</figure>\n";
    page += "<figure>\n<div class=\"heat\">\n<img id=\"heatmap\" alt=\"the difference\" src=\"" +
            pngData(differenceHeatmap(c.match)) + "\">\n" + regionOutlines(c.match) +
            "</div>\n<figcaption>the difference: <span style=\"color:#00c\">blue</span> where "
            "your image is darker, <span style=\"color:#c00\">red</span> where it is brighter, "
            "grey where it matches; the regions the report lists are outlined and "
            "numbered</figcaption>\n</figure>\n</div>\n";
    page += "<p>The reference is the scene under the global settings found (" +
            escapeHtml(departureOptions(c.settings).empty() ? std::string("the defaults")
                                                            : departureOptions(c.settings)) +
            "), rendered by the double-precision CPU reference.</p>\n";
    return page + kFlipScript + "\n</body>\n</html>\n";
}

std::string folderPage(const std::vector<Comparison>& comparisons,
                       const std::vector<std::string>& pageNames, const std::string& table) {
    std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                       "<title>compare: a folder</title>\n" +
                       std::string(kStyle) +
                       "\n</head>\n<body>\n<h1>Images against their scenes</h1>\n<table>\n"
                       "<tr><th>image</th><th>verdict</th><th>matching</th><th>global "
                       "differences</th></tr>\n";
    for (std::size_t k = 0; k < comparisons.size(); ++k) {
        const Comparison& c = comparisons[k];
        const std::string options = departureOptions(c.settings);
        page += "<tr><td><a href=\"" + escapeHtml(pageNames[k]) + "\">" +
                escapeHtml(c.imagePath.filename().string()) + "</a></td><td>" +
                verdictName(c.verdict) + "</td><td>" + percent(c.match.fractionMatching) +
                "</td><td>" + escapeHtml(options.empty() ? "none" : options) + "</td></tr>\n";
    }
    page += "</table>\n<pre id=\"report\">" + escapeHtml(table) + "</pre>\n";
    return page + "<script>document.body.dataset.ready = \"yes\";</script>\n</body>\n</html>\n";
}
