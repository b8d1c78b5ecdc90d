// What a JPEG file's markers say before its pixels are decoded: whether it is whole, and
// the quality its encoder was asked for, estimated from its luminance quantisation table.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

struct JpegFacts {
    // The quality 1..100 whose standard (IJG) luminance table is nearest the file's; none
    // when the file has no 8x8 luminance table.
    std::optional<int> quality;
    bool exactTable = false; // the file's table is the standard one at that quality
};

// Walks the markers of bytes (a JPEG file's whole contents). Throws std::runtime_error
// "PATH: REASON" when the file is cut short: a segment runs past its end, or no
// end-of-image marker follows the image data.
JpegFacts readJpegFacts(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);
