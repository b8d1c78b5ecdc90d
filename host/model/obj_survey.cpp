#include "model/obj_survey.h"

#include "base/parallel.h"
#include "model/obj_statements.h"
#include "scene/scene_lexer.h"

#include <algorithm>
#include <set>

using scene_lexer::isSpace;

namespace {

// The words of a logical line before any '#'.
std::size_t countWords(std::string_view text) {
    std::size_t words = 0;
    bool inWord = false;
    for (const char c : text) {
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
