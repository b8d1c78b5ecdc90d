// The line level of OBJ and MTL text, shared by their readers (obj_reader.h, mtl_reader.h):
// logical lines (a trailing backslash continues a line on the next), their words before
// any '#', and the numbers a statement gives, each wrong one a SceneError at its line.
#pragma once

#include "base/phase_progress.h"
#include "scene/scene_error.h"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

// One logical line: its text (continued lines joined by a space, the comment still on it)
// and the number of its first physical line.
struct LogicalLine {
    std::string_view text;
    int line = 0;
};

// The logical lines of a text in order; LF, CRLF and a lone CR each end a physical line.
// A text that starts at line firstLine of a file numbers its lines from there.
class LineWalker {
  public:
    explicit LineWalker(std::string_view text, int firstLine = 1);
    // The next logical line, or false at the end of the text. The view lives until the
    // next call.
    bool next(LogicalLine& out);
    // Physical lines read so far, and the text's bytes.
    int linesRead() const { return line_ - firstLine_ + 1; }
    std::size_t bytesRead() const { return pos_; }

  private:
    std::string_view text_;
    std::size_t pos_ = 0;
    std::size_t nextCr_ = 0; // the first '\r' at or after pos_, or the text's size
    int firstLine_, line_;
    std::string joined_; // a continued line, put together
};

// A chunk's reading as a share of a phase's progress: its bytes, told every few lines.
class ProgressShare {
  public:
    ProgressShare(PhaseProgress* progress, const LineWalker& lines)
        : progress_(progress), lines_(lines) {}
    void update() {
        if (progress_ && ++lines_since_ == kLines) finish(), lines_since_ = 0;
    }
    void finish() {
        if (!progress_) return;
        progress_->advance(lines_.bytesRead() - told_);
        told_ = lines_.bytesRead();
    }

  private:
    static constexpr int kLines = 1 << 16;
    PhaseProgress* progress_;
    const LineWalker& lines_;
    std::size_t told_ = 0;
    int lines_since_ = 0;
};

// One statement: its first line and its words before any '#'.
struct Statement {
    int line = 0;
    std::vector<std::string_view> words;
};

// Fills statement.words with the words of a logical line before any '#'.
void splitStatement(const LogicalLine& logical, Statement& statement);

// Calls onStatement for each logical line of text that has words.
template <typename OnStatement>
void forEachStatement(std::string_view text, OnStatement onStatement) {
    LineWalker lines(text);
    LogicalLine logical;
    Statement statement; // one for every line: its words' storage is reused
    while (lines.next(logical)) {
        splitStatement(logical, statement);
        if (!statement.words.empty()) onStatement(statement);
    }
}

// The words from index `from` on, joined by single spaces.
std::string joinWords(const std::vector<std::string_view>& words, std::size_t from);

// A reader of one file's statements: the place for its messages.
struct Place {
    const std::string& file;
    int line;
    [[noreturn]] void fail(const std::string& message) const {
        throw SceneError(file, line, message);
    }
};

// The numbers of a statement, at most 7 (`v x y z r g b`, or x y z w), held without a heap
// allocation: a model has millions of such lines.
struct Numbers {
    std::array<double, 7> values{};
    std::size_t count = 0;
    std::size_t size() const { return count; }
    double operator[](std::size_t i) const { return values[i]; }
};

// The words after the keyword as `count` to `count + optional` finite numbers.
Numbers numbers(const Place& place, const Statement& statement, std::size_t count,
                std::string_view what, std::size_t optional = 0);

// The numbers after a keyword of `keywordLength` characters when every word is one that
// scene_lexer::parseNumber reads on its fast path and there are at most 7; false
// otherwise (numbers() then reads the statement and says what is wrong). No '#' may follow.
bool simpleNumbers(std::string_view text, std::size_t keywordLength, Numbers& out);

inline glm::dvec3 clampedColor(const Numbers& values, std::size_t first) {
    return glm::clamp(glm::dvec3(values[first], values[first + 1], values[first + 2]), 0.0, 1.0);
}
