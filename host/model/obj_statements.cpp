#include "model/obj_statements.h"

#include "scene/scene_lexer.h"

#include <algorithm>
#include <bit>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace {

// Where '\n' is first found in [from, to) of data, or `to`. A model's lines are short:
// sixteen bytes at a time for the first few blocks (SSE2, every x86-64), then memchr, whose
// call costs more than a short line's search.
std::size_t findLineFeed(const char* data, std::size_t from, std::size_t to) {
#if defined(__SSE2__)
    const __m128i lineFeed = _mm_set1_epi8('\n');
    for (int block = 0; block < 4 && from + 16 <= to; ++block, from += 16) {
        const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(data + from));
        if (const auto hits = unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, lineFeed))))
            return from + std::size_t(std::countr_zero(hits));
    }
#endif
    const void* hit = from < to ? std::memchr(data + from, '\n', to - from) : nullptr;
    return hit ? std::size_t(static_cast<const char*>(hit) - data) : to;
}

} // namespace

LineWalker::LineWalker(std::string_view text, int firstLine)
    : text_(text), firstLine_(firstLine), line_(firstLine - 1) {
    const void* cr = text.empty() ? nullptr : std::memchr(text.data(), '\r', text.size());
    nextCr_ = cr ? std::size_t(static_cast<const char*>(cr) - text.data()) : text.size();
}

bool LineWalker::next(LogicalLine& out) {
    const std::size_t size = text_.size();
    const char* const data = text_.data();
    // Where c is first found in [from, to), or `to`.
    auto find = [&](char c, std::size_t from, std::size_t to) {
        const void* hit = from < to ? std::memchr(data + from, c, to - from) : nullptr;
        return hit ? std::size_t(static_cast<const char*>(hit) - data) : to;
    };
    joined_.clear();
    int start = 0;
    while (pos_ < size) {
        // Most files have no CR at all: it is looked for once, then again only past it.
        if (nextCr_ < pos_) nextCr_ = find('\r', pos_, size);
        const std::size_t end = findLineFeed(data, pos_, nextCr_);
        std::string_view physical = text_.substr(pos_, end - pos_);
        pos_ = end;
        if (pos_ < size)
            pos_ += (data[pos_] == '\r' && pos_ + 1 < size && data[pos_ + 1] == '\n') ? 2 : 1;
        ++line_;
        if (joined_.empty()) start = line_;
        if (!physical.empty() && physical.back() == '\\') {
            joined_.append(physical.substr(0, physical.size() - 1));
            joined_.push_back(' ');
            if (pos_ < size) continue;
            physical = {};
        } else if (!joined_.empty()) {
            joined_.append(physical);
        }
        out.text = joined_.empty() ? physical : std::string_view(joined_);
        out.line = start;
        return true;
    }
    return false;
}

void splitStatement(const LogicalLine& logical, Statement& statement) {
    statement.line = logical.line;
    statement.words.clear();
    scene_lexer::Tokenizer words{logical.text.substr(0, logical.text.find('#'))};
    for (auto word = words.next(); !word.text.empty(); word = words.next())
        statement.words.push_back(word.text);
}

std::string joinWords(const std::vector<std::string_view>& words, std::size_t from) {
    std::string name;
    for (std::size_t i = from; i < words.size(); ++i) {
        if (i > from) name += ' ';
        name += words[i];
    }
    return name;
}

Numbers numbers(const Place& place, const Statement& statement, std::size_t count,
                std::string_view what, std::size_t optional) {
    const std::size_t given = statement.words.size() - 1;
    if (given < count || given > count + optional) {
        const std::string wanted =
            optional == 0 ? std::to_string(count)
                          : std::to_string(count) + " to " + std::to_string(count + optional);
        place.fail(std::string(what) + " expects " + wanted + " numbers, got " +
                   std::to_string(given));
    }
    Numbers values;
    for (std::size_t i = 1; i < statement.words.size(); ++i) {
        const std::string_view word = statement.words[i];
        double value = 0.0;
        const auto status = scene_lexer::parseNumber(word, value);
        if (status == scene_lexer::NumberStatus::invalid)
            place.fail(std::string(what) + ": '" + std::string(word) + "' is not a number");
        if (status == scene_lexer::NumberStatus::nonFinite)
            place.fail(std::string(what) + ": '" + std::string(word) + "' is not a finite number");
        values.values[values.count++] = value;
    }
    return values;
}

bool simpleNumbers(std::string_view text, std::size_t keywordLength, Numbers& out) {
    // Each number is a whole word: nextSimpleNumber stops at any other word ('#' too).
    scene_lexer::Tokenizer words{text.substr(keywordLength)};
    out.count = 0;
    for (;;) {
        double value = 0.0;
        if (words.nextSimpleNumber(value) == 0) return words.pos == words.text.size();
        if (out.count == out.values.size()) return false;
        out.values[out.count++] = value;
    }
}
