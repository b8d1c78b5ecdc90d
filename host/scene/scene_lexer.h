// The character level of the scene reader: is the file text at all, where are its
// tokens and lines, and what number does a token spell. Kept apart from the grammar
// (scene_parser.cpp) because this is where a 400 MB file spends its time, so each piece here
// is written for speed and tested on its own against the plain definition.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace scene_lexer {

// Whitespace between tokens: space, \t, \n, \v, \f, \r.
enum CharClass : unsigned char { kTokenChar = 0, kSpace = 1, kLineEnd = 2 };

struct CharClasses {
    unsigned char of[256];
    constexpr CharClasses() : of{} {
        for (char c : {' ', '\t', '\v', '\f'})
            of[static_cast<unsigned char>(c)] = kSpace;
        of[static_cast<unsigned char>('\n')] = kLineEnd;
        of[static_cast<unsigned char>('\r')] = kLineEnd;
    }
};
inline constexpr CharClasses kCharClasses{};

inline bool isSpace(char c) {
    return kCharClasses.of[static_cast<unsigned char>(c)] != kTokenChar;
}

#if defined(__SSE2__)
// Which of sixteen bytes (0xFF each) are the whitespace controls \t \n \v \f \r, the
// bytes isSpace takes besides ' ': less '\t' they are 0 to 4, and min(x, 4) == x holds
// for those alone, one unsigned compare for all sixteen (SSE2 has no unsigned <).
inline __m128i whitespaceControls16(__m128i bytes) {
    const __m128i control = _mm_sub_epi8(bytes, _mm_set1_epi8('\t'));
    return _mm_cmpeq_epi8(_mm_min_epu8(control, _mm_set1_epi8(4)), control);
}
#endif

// Why the text is not a text file at all, or nothing: a NUL, a control byte other
// than whitespace, or (with Utf8) bytes that are not UTF-8. Reports the first
// offending offset, counted from `offset` (the text's place in its file, for a part of it
// checked apart). OBJ files pass AnyBytes: their names and comments come in whatever
// encoding the exporter used (a Latin-1 material name), compared as bytes.
enum class TextEncoding { Utf8, AnyBytes };
std::optional<std::string> binaryReason(std::string_view text,
                                        TextEncoding encoding = TextEncoding::Utf8,
                                        std::size_t offset = 0);

// One whitespace-separated word of the text and the line it is on.
struct Token {
    std::string_view text; // empty at the end of the text
    int line = 0;
};

// Splits text into tokens, counting lines (LF, CRLF or a lone CR ends a line).
struct Tokenizer {
    std::string_view text;
    std::size_t pos = 0;
    int line = 1;

    // Moves to the start of the next token (or the end) and returns that offset.
    std::size_t skipSpace() {
        const char* data = text.data();
        const std::size_t size = text.size();
        while (pos < size) {
            const unsigned char cls = kCharClasses.of[static_cast<unsigned char>(data[pos])];
            if (cls == kTokenChar) break;
            // A CR followed by LF is one line end, counted at the LF.
            if (cls == kLineEnd && (data[pos] == '\n' || pos + 1 == size || data[pos + 1] != '\n'))
                ++line;
            ++pos;
        }
        return pos;
    }

    // Moves past the next token if it is the four-character key `lower` (given in lower
    // case: "pos:") in any case, and says whether it did; otherwise the cursor is left at
    // the token's start. One comparison: OR-ing 0x20 into a byte maps only the byte
    // itself and its upper-case letter to a lower-case letter, and only ':' and the
    // control byte 0x1A to ':', which the binary check has already refused.
    bool skipKey(std::string_view lower) {
        const std::size_t start = skipSpace();
        if (lower.size() != 4 || start + 4 > text.size()) return false;
        std::uint32_t word, key;
        std::memcpy(&word, text.data() + start, 4);
        std::memcpy(&key, lower.data(), 4);
        if ((word | 0x20202020u) != key) return false;
        if (start + 4 != text.size() && !isSpace(text[start + 4])) return false;
        pos = start + 4;
        return true;
    }

    // The next token if it is a number that parseNumber reads on its fast path: its
    // length, the value set and the cursor moved past it. Otherwise 0 and the cursor at
    // the token's start, for next() to read it. Reads each character once.
    std::size_t nextSimpleNumber(double& value);

    Token next() {
        skipSpace();
        const char* data = text.data();
        const std::size_t start = pos, size = text.size();
        while (pos < size && kCharClasses.of[static_cast<unsigned char>(data[pos])] == kTokenChar)
            ++pos;
        return {text.substr(start, pos - start), line};
    }
};

// Where each of up to `threads` readers of a large text starts (0: workerThreads(),
// base/parallel.h): 0 for the first, then the first object keyword ('sphere',
// 'triangle', 'light' in any case, a whole token) at or after each further equal share,
// skipping a share that holds none. No reader gets less than minChunkBytes.
std::vector<std::size_t> chunkStarts(std::string_view text, unsigned threads,
                                     std::size_t minChunkBytes);

enum class NumberStatus { ok, invalid, nonFinite };

// The whole token as a decimal number, correctly rounded to double: what from_chars
// accepts in general format (-2.6748e-08, .44, 1., -0, and also nan and inf, which are
// then non-finite) plus one leading '+'. Hex never gets through, and anything left over
// makes the token invalid. A number too close to zero for a double reads as zero.
NumberStatus parseNumber(std::string_view token, double& value);

// The same through from_chars alone: the definition that parseNumber's fast path is
// tested against.
NumberStatus parseNumberSlow(std::string_view token, double& value);

} // namespace scene_lexer
