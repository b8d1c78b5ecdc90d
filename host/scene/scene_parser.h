// The grammar of the scene file (docs/model.md, "Scene file"): one reader walks the tokens of
// a stretch of text, one function per object, with a message for every way the text
// can be wrong. scene.cpp runs one reader over a small file, or several over the shares
// of a large one and joins what they read.
#pragma once

#include "scene/scene.h"
#include "scene/scene_error.h"
#include "scene/scene_lexer.h"

#include <cstddef>
#include <cstdint>
#include <stop_token>
#include <string>
#include <vector>

namespace scene_parser {

constexpr std::size_t kNowhere = std::string_view::npos;

// A warning with its line counted from where its reader started; the reader of a chunk
// read ahead learns its first line only when the chunk is confirmed.
struct Warning {
    int line;
    std::string message;
};

struct Key;
struct Number;

// A place in the file's grammar, named for messages: "the sphere's radius", "the
// triangle's vertex 2 'dif:'", "the ambient colour", "'sphere'" (the keyword itself,
// key == nullptr), "the object count" (neither). Turned into words only on error.
struct Field {
    const Key* key = nullptr;
    const char* object = nullptr; // "sphere", "triangle", "light"
    int vertex = 0;               // 1 to 3 on a triangle
};

// Reads objects into `scene` from where `tokens` stands; errors are thrown as SceneError.
struct Reader {
    scene_lexer::Tokenizer tokens;
    const std::string& file;
    Scene scene{};
    std::vector<Warning> warnings{};
    std::uint64_t claimedCount = 0; // the header's object count
    std::uint64_t objectsRead = 0;
    std::size_t stopAt = kNowhere;       // where the next chunk's first object starts
    std::size_t sizeUntil = 0;           // the end of the text whose objects end up in `scene`
    std::size_t objectsStart = kNowhere; // where this reader's first object starts
    std::uint64_t objectsHere = 0;       // objects this reader has read
    Field previous{};                    // the field read last, for "expected X after Y"
    int lastLine = 1;                    // of the last token read; end-of-file errors point here
    int keyLine = 0; // of the last key read; warnings about its field point here

    // The object count and the ambient colour.
    void readHeader();
    // Reads objects in file order until the header's count is reached, or until the
    // next token starts at stopAt while an object is expected: true then.
    bool readObjects();
    // After the counted objects: the end of the file, or an error naming what follows.
    void expectEnd();
    // A chunk read ahead: objects, however many, from its start to stopAt or the end.
    // False if cancelled before getting there.
    bool readChunk(const std::stop_token& cancel);

  private:
    [[noreturn]] void fail(int line, const std::string& message) const;
    void warn(int line, const std::string& message);
    scene_lexer::Token next();
    void expectKey(const Field& field);
    Number readNumber(const Field& field);
    Number readScalarField(const Field& field);
    glm::dvec3 readVec3Field(const Field& field);
    glm::dvec3 readColorField(const Field& field, bool warnAboveOne);
    Material readMaterial(const char* object, int vertex);
    Sphere readSphere();
    Triangle readTriangle(int keywordLine);
    Light readLight();
    std::uint64_t readObjectCount();
    void reserveAtTheRateSoFar();
    void readObject();
};

} // namespace scene_parser
