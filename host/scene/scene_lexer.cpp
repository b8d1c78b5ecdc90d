#include "scene/scene_lexer.h"

#include "base/parallel.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <system_error>

namespace scene_lexer {
namespace {

char toLower(char c) {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

// Length of the well-formed UTF-8 sequence that starts with the non-ASCII byte
// text[i], or 0 (stray continuation byte, overlong form, surrogate, past U+10FFFF,
// cut short by the end of the text).
std::size_t utf8SequenceLength(std::string_view text, std::size_t i) {
    const auto lead = static_cast<unsigned char>(text[i]);
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xBF; // allowed range of the second byte
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        if (lead == 0xE0) low = 0xA0;  // overlong
        if (lead == 0xED) high = 0x9F; // surrogates
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        if (lead == 0xF0) low = 0x90;  // overlong
        if (lead == 0xF4) high = 0x8F; // above U+10FFFF
    } else {
        return 0;
    }
    if (i + length > text.size()) return 0;
    for (std::size_t k = 1; k < length; ++k) {
        const auto byte = static_cast<unsigned char>(text[i + k]);
        if (byte < (k == 1 ? low : 0x80) || byte > (k == 1 ? high : 0xBF)) return 0;
    }
    return length;
}

// Flags (bit 7 of each byte) the bytes of an 8-byte word that are not printable ASCII
// or whitespace: controls other than \t..\r, DEL, and every byte >= 0x80. Bytes are
// first cut to 7 bits, so the additions below never carry into the next byte.
std::uint64_t unusualBytes(std::uint64_t word) {
    constexpr std::uint64_t ones = 0x0101010101010101ull, highs = 0x8080808080808080ull;
    const std::uint64_t low7 = word & ~highs;
    const std::uint64_t atLeast20 = low7 + ones * (0x80 - 0x20);
    const std::uint64_t atLeast09 = low7 + ones * (0x80 - 0x09);
    const std::uint64_t atLeast0E = low7 + ones * (0x80 - 0x0E);
    const std::uint64_t isDel = low7 + ones * (0x80 - 0x7F);
    const std::uint64_t whitespace = atLeast09 & ~atLeast0E;
    return (word | isDel | (~atLeast20 & ~whitespace)) & highs;
}

// from_chars reports both 1e999 and 1e-999 as out of range and leaves the value
// unset. Tell them apart by the power of ten of the leading significant digit:
// below zero the number is merely too close to zero for a double (read as zero,
// as strtod would), otherwise it is too large (non-finite).
bool isUnderflow(std::string_view number) {
    long long power = 0;
    bool afterPoint = false, significant = false;
    std::size_t i = 0;
    for (; i < number.size() && toLower(number[i]) != 'e'; ++i) {
        const char c = number[i];
        if (c == '.') {
            afterPoint = true;
        } else if ((c >= '1' && c <= '9') || (c == '0' && significant)) {
            if (!significant && afterPoint)
                --power;
            else if (significant && !afterPoint)
                ++power;
            significant = true;
        } else if (c == '0' && afterPoint) {
            --power; // a leading zero after the point
        }
    }
    long long exponent = 0;
    bool negative = false;
    for (++i; i < number.size(); ++i) {
        if (number[i] == '-')
            negative = true;
        else if (number[i] >= '0' && number[i] <= '9')
            exponent = std::min(exponent * 10 + (number[i] - '0'), 1'000'000'000LL);
    }
    return power + (negative ? -exponent : exponent) < 0;
}

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

// Powers of ten that a double holds exactly.
constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                        1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                        1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// Appends the run of digits at p to mantissa (wrapping if there are too many; the
// caller counts them) and returns where the run ends.
const char* readDigits(const char* p, const char* const end, std::uint64_t& mantissa) {
    for (; p != end && isDigit(*p); ++p)
        mantissa = mantissa * 10 + std::uint64_t(*p - '0');
    return p;
}

// The common case of a scene file, a decimal with few significant digits and a small
// exponent, read in one pass: the digits as an integer m <= 2^53 and a power of ten
// 10^e with |e| <= 22 are both exact doubles, so the single IEEE multiplication or
// division m * 10^e (m / 10^-e) is the correctly rounded value (Clinger's fast path),
// which is what from_chars computes too. Reads from p as far as the number goes and
// returns where it stopped, or nullptr for anything else (more digits, a larger
// exponent, no digits, nan, inf), which from_chars then reads.
const char* scanSimpleDecimal(const char* p, const char* const end, double& value) {
    bool negative = false;
    if (p != end && (*p == '-' || *p == '+')) negative = *p++ == '-';
    // Up to 19 digits, leading zeros included, cannot overflow the integer; more go to
    // from_chars (the loops run on, wrapping harmlessly, only to find the token's end).
    std::uint64_t mantissa = 0;
    const char* const integerStart = p;
    p = readDigits(p, end, mantissa);
    std::ptrdiff_t digits = p - integerStart, fractionDigits = 0;
    if (p != end && *p == '.') {
        const char* const fractionStart = ++p;
        p = readDigits(p, end, mantissa);
        fractionDigits = p - fractionStart;
        digits += fractionDigits;
    }
    if (digits == 0 || digits > 19) return nullptr;
    int exponent = 0;
    if (p != end && (*p == 'e' || *p == 'E')) {
        ++p;
        bool negativeExponent = false;
        if (p != end && (*p == '-' || *p == '+')) negativeExponent = *p++ == '-';
        if (p == end || !isDigit(*p)) return nullptr;
        for (; p != end && isDigit(*p); ++p)
            exponent = std::min(exponent * 10 + (*p - '0'), 100000);
        if (negativeExponent) exponent = -exponent;
    }
    const int power = exponent - int(fractionDigits);
    if (mantissa > (std::uint64_t(1) << 53) || power < -22 || power > 22) return nullptr;
    const double m = double(mantissa);
    const double magnitude =
        power >= 0 ? m * kExactPowersOfTen[power] : m / kExactPowersOfTen[-power];
    value = negative ? -magnitude : magnitude;
    return p;
}

#if defined(__SSE2__)
// Whether the sixteen bytes at p are all printable ASCII or whitespace (unusualBytes finds
// none in either half): one SSE2 compare of each kind for all sixteen (every x86-64).
bool plainBytes16(const char* p) {
    const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    // Below 0x20 as signed bytes: the controls, and every byte >= 0x80.
    const __m128i low = _mm_cmplt_epi8(bytes, _mm_set1_epi8(0x20));
    const __m128i space = whitespaceControls16(bytes);
    const __m128i del = _mm_cmpeq_epi8(bytes, _mm_set1_epi8(0x7F));
    return _mm_movemask_epi8(_mm_or_si128(_mm_andnot_si128(space, low), del)) == 0;
}
#endif

} // namespace

std::optional<std::string> binaryReason(std::string_view text, TextEncoding encoding,
                                        std::size_t offset) {
    static const char hex[] = "0123456789abcdef";
    const std::size_t size = text.size();
    for (std::size_t i = 0; i < size;) {
#if defined(__SSE2__)
        if (i + 16 <= size && plainBytes16(text.data() + i)) {
            i += 16;
            continue;
        }
#endif
        // Eight plain bytes at a time; a word with anything unusual goes byte by byte.
        if (i + 8 <= size) {
            std::uint64_t word;
            std::memcpy(&word, text.data() + i, 8);
            if (unusualBytes(word) == 0) {
                i += 8;
                continue;
            }
        }
        const auto c = static_cast<unsigned char>(text[i]);
        if ((c >= 0x20 && c < 0x7F) || isSpace(text[i])) {
            ++i;
        } else if (c == 0) {
            return "NUL byte at offset " + std::to_string(offset + i);
        } else if (c < 0x80) {
            return std::string("control byte 0x") + hex[c >> 4] + hex[c & 15] + " at offset " +
                   std::to_string(offset + i);
        } else if (encoding == TextEncoding::AnyBytes) {
            ++i;
        } else if (std::size_t length = utf8SequenceLength(text, i)) {
            i += length;
        } else {
            return "invalid UTF-8 at offset " + std::to_string(offset + i);
        }
    }
    return std::nullopt;
}

namespace {

bool equalsIgnoreCase(std::string_view token, std::string_view lower) {
    if (token.size() != lower.size()) return false;
    for (std::size_t i = 0; i < token.size(); ++i)
        if (toLower(token[i]) != lower[i]) return false;
    return true;
}

bool isObjectKeyword(std::string_view token) {
    return equalsIgnoreCase(token, "triangle") || equalsIgnoreCase(token, "sphere") ||
           equalsIgnoreCase(token, "light");
}

constexpr std::size_t kNowhere = std::string_view::npos;

// The offset of the first object keyword that starts a token in [from, until), or
// kNowhere. `from` inside a token skips the rest of that token.
std::size_t objectKeywordBetween(std::string_view text, std::size_t from, std::size_t until) {
    std::size_t pos = from;
    while (pos > 0 && pos < text.size() && !isSpace(text[pos - 1]) && !isSpace(text[pos]))
        ++pos;
    Tokenizer tokens{text, pos};
    for (;;) {
        const std::size_t start = tokens.skipSpace();
        if (start >= until || start == text.size()) return kNowhere;
        if (isObjectKeyword(tokens.next().text)) return start;
    }
}

} // namespace

std::vector<std::size_t> chunkStarts(std::string_view text, unsigned threads,
                                     std::size_t minChunkBytes) {
    const std::size_t chunks = chunkCount(text.size(), threads, minChunkBytes);
    std::vector<std::size_t> starts{0};
    for (std::size_t k = 1; k < chunks; ++k) {
        const std::size_t share = text.size() * k / chunks, next = text.size() * (k + 1) / chunks;
        const std::size_t start =
            objectKeywordBetween(text, std::max(share, starts.back() + 1), next);
        if (start != kNowhere) starts.push_back(start);
    }
    return starts;
}

NumberStatus parseNumberSlow(std::string_view token, double& value) {
    if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+')
        token.remove_prefix(1);
    const char* end = token.data() + token.size();
    const auto [stop, error] = std::from_chars(token.data(), end, value);
    if (error == std::errc::invalid_argument || stop != end) return NumberStatus::invalid;
    if (error == std::errc::result_out_of_range) {
        if (!isUnderflow(token)) return NumberStatus::nonFinite;
        value = token[0] == '-' ? -0.0 : 0.0;
    }
    return std::isfinite(value) ? NumberStatus::ok : NumberStatus::nonFinite;
}

NumberStatus parseNumber(std::string_view token, double& value) {
    const char* end = token.data() + token.size();
    if (scanSimpleDecimal(token.data(), end, value) == end) return NumberStatus::ok;
    return parseNumberSlow(token, value);
}

std::size_t Tokenizer::nextSimpleNumber(double& value) {
    const std::size_t start = skipSpace();
    const char* const end = text.data() + text.size();
    const char* stop = scanSimpleDecimal(text.data() + start, end, value);
    if (stop == nullptr || (stop != end && !isSpace(*stop))) return 0; // not all of a token
    pos = std::size_t(stop - text.data());
    return pos - start;
}

} // namespace scene_lexer
