#include "model/obj_survey.h"

#include "base/parallel.h"
#include "model/obj_statements.h"
#include "scene/scene_lexer.h"

#include <algorithm>
#include <set>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

using scene_lexer::isSpace;

namespace {

// The bits set in a 16-bit mask, in registers: std::popcount is a library call where the
// machine's baseline has no POPCNT instruction (x86-64's has not).
std::size_t bitsSet16(unsigned mask) {
    mask -= (mask >> 1) & 0x5555u;
    mask = (mask & 0x3333u) + ((mask >> 2) & 0x3333u);
    mask = (mask + (mask >> 4)) & 0x0F0Fu;
    return (mask + (mask >> 8)) & 0x1Fu;
}

// The words of a logical line before any '#'. A model's face lines are most of its bytes:
// sixteen of them at a time where the machine has SSE2 (every x86-64), each a bit of a
// mask, a word's first byte being a word byte after a space.
std::size_t countWords(std::string_view text) {
    std::size_t words = 0;
    bool inWord = false;
    std::size_t i = 0;
#if defined(__SSE2__)
    const __m128i blank = _mm_set1_epi8(' '), hash = _mm_set1_epi8('#');
    for (; i + 16 <= text.size(); i += 16) {
        const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(text.data() + i));
        const __m128i space =
            _mm_or_si128(_mm_cmpeq_epi8(bytes, blank), scene_lexer::whitespaceControls16(bytes));
        unsigned wordBytes = ~unsigned(_mm_movemask_epi8(space)) & 0xFFFFu;
        const auto hashes = unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, hash)));
        if (hashes != 0) wordBytes &= (hashes & (0u - hashes)) - 1; // the bytes before it
        words += bitsSet16(wordBytes & ~((wordBytes << 1) | unsigned(inWord)));
        if (hashes != 0) return words;
        inWord = (wordBytes >> 15) != 0;
    }
#endif
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '#') break;
        const bool space = isSpace(c);
        words += !space && !inWord;
        inWord = !space;
    }
    return words;
}

void countFace(ObjChunkSurvey& survey, std::size_t corners) {
    ++survey.faces;
    survey.facePositions += corners;
    survey.polygons += corners != 3;
    survey.triangles += corners >= 3 ? corners - 2 : 0; // fewer is an error in the second pass
}

} // namespace

ObjKeyword objKeyword(std::string_view keyword) {
    if (keyword == "v") return ObjKeyword::position;
    if (keyword == "vn") return ObjKeyword::normal;
    if (keyword == "vt") return ObjKeyword::texcoord;
    if (keyword == "f") return ObjKeyword::face;
    if (keyword == "mtllib") return ObjKeyword::mtllib;
    if (keyword == "usemtl") return ObjKeyword::usemtl;
    // parameter-space vertices, object and group names, smoothing groups
    if (keyword == "vp" || keyword == "o" || keyword == "g" || keyword == "s")
        return ObjKeyword::skipped;
    return ObjKeyword::ignored;
}

std::vector<std::size_t> objChunkStarts(std::string_view text, unsigned most,
                                        std::size_t minChunkBytes) {
    if (most == 0) most = kObjChunksPerThread * workerThreads();
    const std::size_t chunks = chunkCount(text.size(), most, minChunkBytes);
    std::vector<std::size_t> starts{0};
    for (std::size_t k = 1; k < chunks; ++k) {
        std::size_t from = std::max(text.size() * k / chunks, starts.back());
        for (;;) {
            const std::size_t lf = text.find('\n', from);
            if (lf == std::string_view::npos || lf + 1 >= text.size()) return starts;
            // The physical line that ends here: does a backslash continue it?
            const std::size_t end = lf > 0 && text[lf - 1] == '\r' ? lf - 1 : lf;
            from = lf + 1;
            if (end == 0 || text[end - 1] != '\\') break;
        }
        starts.push_back(from);
    }
    return starts;
}

ObjChunkSurvey surveyObjChunk(std::string_view chunk, PhaseProgress* progress) {
    ObjChunkSurvey survey;
    LineWalker lines(chunk);
    LogicalLine logical;
    Statement statement;
    std::set<std::string, std::less<>> ignored;
    ProgressShare share(progress, lines);
    while (lines.next(logical)) {
        share.update();
        const std::string_view text = logical.text;
        // The common statements by their first characters, without splitting them.
        if (const std::optional<ObjKeyword> keyword = leadingKeyword(text)) {
            if (*keyword == ObjKeyword::face)
                countFace(survey, countWords(text) - 1);
            else
                ++(*keyword == ObjKeyword::position ? survey.positions
                   : *keyword == ObjKeyword::normal ? survey.normals
                                                    : survey.texcoords);
            continue;
        }
        splitStatement(logical, statement);
        if (statement.words.empty()) continue;
        const ObjKeyword keyword = objKeyword(statement.words[0]);
        switch (keyword) {
        case ObjKeyword::position:
            ++survey.positions;
            break;
        case ObjKeyword::normal:
            ++survey.normals;
            break;
        case ObjKeyword::texcoord:
            ++survey.texcoords;
            break;
        case ObjKeyword::face:
            countFace(survey, statement.words.size() - 1);
            break;
        case ObjKeyword::skipped:
            break;
        case ObjKeyword::mtllib:
        case ObjKeyword::usemtl:
        case ObjKeyword::ignored: {
            ObjEvent event{keyword, logical.line, survey.faces, {}};
            if (keyword == ObjKeyword::mtllib)
                event.words.assign(statement.words.begin() + 1, statement.words.end());
            else if (keyword == ObjKeyword::usemtl)
                event.words.push_back(joinWords(statement.words, 1));
            else if (ignored.insert(std::string(statement.words[0])).second)
                event.words.emplace_back(statement.words[0]);
            else
                break;
            survey.events.push_back(std::move(event));
            break;
        }
        }
    }
    share.finish();
    survey.lines = lines.linesRead();
    return survey;
}
