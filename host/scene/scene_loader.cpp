// Text to a Scene (scene_loader.h). The grammar is scene_parser.*; this file decides who
// reads what.
//
// A large file is read by several threads, each from an object keyword near its share
// of the text, guessing that an object starts there. Each guess is confirmed only when
// the reader before it arrives at that very token expecting an object. Whatever goes
// wrong in a chunk read ahead (an error, a count that does not add up) is not
// reported from there: the text from that chunk on is read again in order, so every
// message, line number and warning is exactly what reading the file in one pass gives.
#include "scene/scene_loader.h"

#include "base/parallel.h"
#include "base/populated_memory.h"
#include "scene/file_format.h"
#include "scene/mapped_file.h"
#include "scene/scene_lexer.h"
#include "scene/scene_parser.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stop_token>
#include <system_error>

using scene_lexer::Tokenizer;
using scene_parser::kNowhere;
using scene_parser::Reader;
using scene_parser::Warning;

namespace {

// Makes room for exactly `capacity` elements, the new block's pages mapped before they are
// written (base/populated_memory.h): a million triangles take 300 MiB, and taking that as
// 75,000 page faults costs a tenth of a second more.
template <typename T> void reserveExactly(std::vector<T>& values, std::size_t capacity) {
    if (capacity <= values.capacity()) return;
    std::vector<T> larger;
    larger.reserve(capacity);
    populatePages(larger.data(), capacity * sizeof(T));
    larger.insert(larger.end(), values.begin(), values.end());
    values.swap(larger);
}

void appendWarnings(Scene& scene, const Reader& reader, int firstLine) {
    for (const Warning& warning : reader.warnings)
        scene.warnings.push_back(sceneLocation(reader.file, warning.line + firstLine - 1) +
                                 "warning: " + warning.message);
}

// Appends from's objects, their lines (counted from a reader's first line) made the
// file's: a reader that started at line firstLine counted it as line 1.
template <typename T>
void appendAll(std::vector<T>& into, const std::vector<T>& from, int firstLine) {
    const std::size_t start = into.size();
    into.insert(into.end(), from.begin(), from.end());
    for (std::size_t k = start; k < into.size(); ++k)
        into[k].line += firstLine - 1;
}

// Joins the scenes of readers that read consecutive parts of the text, in order.
Scene joinScenes(const std::vector<std::pair<Reader*, int>>& parts) {
    std::size_t spheres = 0, triangles = 0, lights = 0;
    for (const auto& [reader, firstLine] : parts) {
        spheres += reader->scene.spheres.size();
        triangles += reader->scene.triangles.size();
        lights += reader->scene.lights.size();
    }
    Scene scene = std::move(parts.front().first->scene);
    reserveExactly(scene.spheres, spheres);
    reserveExactly(scene.triangles, triangles);
    reserveExactly(scene.lights, lights);
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const auto& [reader, firstLine] = parts[i];
        if (i > 0) {
            appendAll(scene.spheres, reader->scene.spheres, firstLine);
            appendAll(scene.triangles, reader->scene.triangles, firstLine);
            appendAll(scene.lights, reader->scene.lights, firstLine);
        }
        appendWarnings(scene, *reader, firstLine);
    }
    return scene;
}

Scene parseText(std::string_view text, const std::string& fileName,
                const std::vector<std::size_t>& starts) {
    Reader first{Tokenizer{text}, fileName};
    first.sizeUntil = text.size(); // the chunks read ahead are appended to its arrays
    std::vector<Reader> ahead;
    ahead.reserve(starts.size() - 1);
    for (std::size_t k = 1; k < starts.size(); ++k) {
        ahead.push_back(Reader{Tokenizer{text, starts[k]}, fileName});
        ahead.back().stopAt = k + 1 < starts.size() ? starts[k + 1] : kNowhere;
        ahead.back().sizeUntil = k + 1 < starts.size() ? starts[k + 1] : text.size();
    }
    // Reader 0 is the first, from the header on; reader k > 0 reads ahead[k - 1], each on a
    // thread of its own (the chunks are as many as the thread policy allows, chunkStarts).
    // When the first finds the file's end before its chunk's, or throws, the others stop.
    std::vector<char> complete(ahead.size(), 0);
    std::stop_source cancel;
    bool endedEarly = false;
    first.stopAt = starts.size() > 1 ? starts[1] : kNowhere;
    parallelFor(
        starts.size(),
        [&](std::size_t reader) {
            if (reader > 0) {
                try {
                    complete[reader - 1] = ahead[reader - 1].readChunk(cancel.get_token());
                } catch (...) {
                    // Read again in order below, which says what is wrong.
                }
                return;
            }
            try {
                first.readHeader();
                if (!first.readObjects()) {
                    endedEarly = true;
                    cancel.request_stop();
                    first.expectEnd();
                }
            } catch (...) {
                cancel.request_stop();
                throw;
            }
        },
        unsigned(starts.size()));
    if (endedEarly) return joinScenes({{&first, 1}});

    // Confirm the chunks in order while the counts add up.
    std::vector<std::pair<Reader*, int>> parts{{&first, 1}};
    int line = first.tokens.line; // of the next chunk's first token
    std::uint64_t objectsSoFar = first.objectsRead;
    std::size_t k = 0;
    for (; k < ahead.size(); ++k) {
        const std::uint64_t total = objectsSoFar + ahead[k].objectsRead;
        const bool last = k + 1 == ahead.size();
        if (!complete[k] || total > first.claimedCount || (last && total != first.claimedCount))
            break;
        parts.emplace_back(&ahead[k], line);
        line += ahead[k].tokens.line - 1;
        objectsSoFar = total;
    }
    // From the first chunk that does not add up, read in order to the end.
    std::optional<Reader> rest;
    if (k < ahead.size()) {
        rest.emplace(Reader{Tokenizer{text, starts[k + 1], line}, fileName});
        rest->claimedCount = first.claimedCount;
        rest->objectsRead = objectsSoFar;
        rest->lastLine = line;
        rest->sizeUntil = text.size();
        rest->readObjects();
        rest->expectEnd();
        parts.emplace_back(&*rest, 1);
    }
    return joinScenes(parts);
}

} // namespace

Scene parseScene(std::string_view text, const std::string& fileName,
                 const SceneParseOptions& options) {
    if (text.empty()) throw SceneError(fileName, 0, "the file is empty");
    if (const auto format = otherFileFormat(text))
        throw SceneError(fileName, 0, otherFormatMessage(*format, fileName, ExpectedFile::Scene));
    if (const auto reason = scene_lexer::binaryReason(text))
        throw SceneError(fileName, 0, "the file is binary (" + *reason + ")");
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3); // UTF-8 byte-order mark
    return parseText(text, fileName,
                     scene_lexer::chunkStarts(text, options.threads, options.minChunkBytes));
}

Scene parseScene(std::string_view text, const std::string& fileName) {
    return parseScene(text, fileName, SceneParseOptions{});
}
