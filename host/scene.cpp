// The scene file reader (SPEC.md, "Scene file"): a token cursor, one function per
// object, and a message for every way a file can be wrong. Messages name the
// object and the field and say what was expected, so they can be fixed without
// reading this code.
//
// A large file is read by several threads, each from an object keyword near its share
// of the text, guessing that an object starts there. Each guess is confirmed only when
// the reader before it arrives at that very token expecting an object. Whatever goes
// wrong in a chunk read ahead (an error, a count that does not add up) is not
// reported from there: the text from that chunk on is read again in order, so every
// message, line number and warning is exactly what reading the file in one pass gives.
#include "scene.h"

#include "scene_file.h"
#include "scene_text.h"

#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stop_token>
#include <sys/mman.h>
#include <system_error>
#include <thread>

using scene_text::NumberStatus;
using scene_text::Token;
using scene_text::Tokenizer;

namespace {

std::string location(const std::string& file, int line) {
    return line > 0 ? file + ":" + std::to_string(line) + ": " : file + ": ";
}

char toLower(char c) {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

// Keywords and keys are case-insensitive; `lower` is given in lower case.
bool equalsIgnoreCase(std::string_view token, std::string_view lower) {
    if (token.size() != lower.size()) return false;
    for (size_t i = 0; i < token.size(); ++i)
        if (toLower(token[i]) != lower[i]) return false;
    return true;
}

// A token as messages show it: quoted and cut short if long (a runaway token
// could be megabytes); the end of the file by name.
// (Built with += because GCC 12 gives a false -Wrestrict on "'" + std::string(...).)
std::string quote(std::string_view token) {
    if (token.empty()) return "the end of the file";
    constexpr size_t maxShown = 40;
    std::string text = "'";
    if (token.size() <= maxShown) {
        text += token;
    } else {
        size_t cut = maxShown; // back up to a character boundary so the message stays UTF-8
        while (cut > 0 && (static_cast<unsigned char>(token[cut]) & 0xC0) == 0x80)
            --cut;
        text += token.substr(0, cut);
        text += "...";
    }
    return text += "'";
}

std::string objects(std::uint64_t count) {
    return std::to_string(count) + (count == 1 ? " object" : " objects");
}

struct Key {
    std::string_view text; // as written in the file, lower case
    const char* name;      // as messages name the field
};
constexpr Key position{"pos:", "position"}, radius{"rad:", "radius"}, normal{"nor:", "normal"},
    diffuse{"dif:", "'dif:'"}, specular{"spe:", "'spe:'"}, shininess{"shi:", "shininess"},
    colour{"col:", "colour"}, ambient{"amb:", "ambient colour"};

// A place in the file's grammar, named for messages: "the sphere's radius", "the
// triangle's vertex 2 'dif:'", "the ambient colour", "'sphere'" (the keyword itself,
// key == nullptr), "the object count" (neither). Turned into words only on error.
struct Field {
    const Key* key = nullptr;
    const char* object = nullptr; // "sphere", "triangle", "light"
    int vertex = 0;               // 1 to 3 on a triangle
};

std::string describe(const Field& field) {
    if (!field.key) return field.object ? quote(field.object) : "the object count";
    std::string text = "the ";
    if (field.object) (text += field.object) += "'s ";
    if (field.vertex > 0) (text += "vertex ") += std::to_string(field.vertex) + " ";
    return text += field.key->name;
}

struct Number {
    double value;
    std::string_view text; // as written, for messages
    int line;
};

// Makes room for exactly `capacity` elements, the new block's pages mapped in one call
// before they are written (MADV_POPULATE_WRITE, Linux 5.14; only advice, ignored where
// unknown): a million triangles take 300 MiB, and taking that as 75,000 page faults
// costs a tenth of a second more.
template <typename T> void reserveExactly(std::vector<T>& values, std::size_t capacity) {
    if (capacity <= values.capacity()) return;
    std::vector<T> larger;
    larger.reserve(capacity);
    constexpr std::uintptr_t page = 4096;
    const auto address = reinterpret_cast<std::uintptr_t>(larger.data());
    const std::uintptr_t begin = (address + page - 1) / page * page;
    const std::uintptr_t end = (address + capacity * sizeof(T)) / page * page;
    if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
    larger.insert(larger.end(), values.begin(), values.end());
    values.swap(larger);
}

// A warning with its line counted from where its reader started; the reader of a chunk
// read ahead learns its first line only when the chunk is confirmed.
struct Warning {
    int line;
    std::string message;
};

constexpr std::size_t kNowhere = std::string_view::npos;

struct Parser {
    Tokenizer tokens;
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

    [[noreturn]] void fail(int line, const std::string& message) const {
        throw SceneError(file, line, message);
    }

    void warn(int line, const std::string& message) { warnings.push_back({line, message}); }

    Token next() {
        Token token = tokens.next();
        if (token.text.empty()) token.line = lastLine;
        lastLine = token.line;
        return token;
    }

    void expectKey(const Field& field) {
        if (tokens.skipKey(field.key->text)) {
            keyLine = lastLine = tokens.line;
            return;
        }
        const Token token = next();
        keyLine = token.line;
        const std::string_view key = field.key->text;
        if (equalsIgnoreCase(token.text, key)) return;
        if (token.text.size() > key.size() &&
            equalsIgnoreCase(token.text.substr(0, key.size()), key))
            fail(token.line, "the key '" + std::string(key) +
                                 "' must be separated from its numbers by whitespace, found " +
                                 quote(token.text));
        std::string message = "expected '" + std::string(key) + "' after " + describe(previous) +
                              ", found " + quote(token.text);
        if (field.vertex > 1 && field.key == &position)
            message += " (a triangle has three vertices)";
        fail(token.line, message);
    }

    Number readNumber(const Field& field) {
        double value = 0.0;
        if (const std::size_t length = tokens.nextSimpleNumber(value)) {
            lastLine = tokens.line;
            return {value, tokens.text.substr(tokens.pos - length, length), tokens.line};
        }
        const Token token = next();
        const NumberStatus status = scene_text::parseNumber(token.text, value);
        if (status == NumberStatus::nonFinite)
            fail(token.line, "non-finite number " + quote(token.text) + " for " + describe(field));
        if (status == NumberStatus::invalid)
            fail(token.line,
                 "expected a number for " + describe(field) + ", found " + quote(token.text));
        return {value, token.text, token.line};
    }

    // "key: number"; the caller checks the range, as it knows what the number means.
    Number readScalarField(const Field& field) {
        expectKey(field);
        const Number number = readNumber(field);
        previous = field;
        return number;
    }

    // "key: x y z" for a position or a normal.
    glm::dvec3 readVec3Field(const Field& field) {
        expectKey(field);
        glm::dvec3 v;
        for (int i = 0; i < 3; ++i)
            v[i] = readNumber(field).value;
        previous = field;
        return v;
    }

    // "key: r g b". Negative is an error; above 1 is fine for lights and the ambient
    // colour (bright lights) but gets a warning for dif and spe (the mix extrapolates).
    glm::dvec3 readColourField(const Field& field, bool warnAboveOne) {
        expectKey(field);
        glm::dvec3 c;
        bool warned = false;
        for (int i = 0; i < 3; ++i) {
            const Number number = readNumber(field);
            if (number.value < 0.0)
                fail(number.line, "negative colour value " + std::string(number.text) + " in " +
                                      describe(field));
            if (warnAboveOne && number.value > 1.0 && !warned) {
                warn(number.line, describe(field) + " " + std::string(number.text) +
                                      " is above 1; used as given");
                warned = true;
            }
            c[i] = number.value;
        }
        previous = field;
        return c;
    }

    Material readMaterial(const char* object, int vertex) {
        Material m;
        m.diffuse = readColourField({&diffuse, object, vertex}, true);
        m.specular = readColourField({&specular, object, vertex}, true);
        const Field field{&shininess, object, vertex};
        const Number s = readScalarField(field);
        if (s.value < 0.0)
            fail(s.line, describe(field) + " must not be negative, found " + std::string(s.text));
        m.shininess = s.value;
        return m;
    }

    Sphere readSphere() {
        Sphere sphere;
        previous = {nullptr, "sphere"};
        sphere.center = readVec3Field({&position, "sphere"});
        const Field field{&radius, "sphere"};
        const Number r = readScalarField(field);
        if (!(r.value > 0.0))
            fail(r.line, describe(field) + " must be positive, found " + std::string(r.text));
        sphere.radius = r.value;
        sphere.material = readMaterial("sphere", 0);
        return sphere;
    }

    // Degenerate triangles are legal (SPEC.md): kept as given, with a warning.
    Triangle readTriangle(int keywordLine) {
        Triangle triangle;
        previous = {nullptr, "triangle"};
        for (int v = 1; v <= 3; ++v) {
            Vertex& vertex = triangle.vertices[v - 1];
            vertex.position = readVec3Field({&position, "triangle", v});
            vertex.normal = readVec3Field({&normal, "triangle", v});
            if (vertex.normal == glm::dvec3(0.0))
                warn(keyLine, describe({&normal, "triangle", v}) + " has zero length");
            vertex.material = readMaterial("triangle", v);
        }
        const glm::dvec3 a = triangle.vertices[0].position, b = triangle.vertices[1].position,
                         c = triangle.vertices[2].position;
        if (glm::cross(b - a, c - a) == glm::dvec3(0.0))
            warn(keywordLine,
                 "the triangle has zero area (its vertices are collinear or coincide)");
        return triangle;
    }

    Light readLight() {
        Light light;
        previous = {nullptr, "light"};
        light.position = readVec3Field({&position, "light"});
        light.color = readColourField({&colour, "light"}, false);
        return light;
    }

    // A plain non-negative decimal integer, nothing else (no sign, point or exponent).
    std::uint64_t readObjectCount() {
        const Token token = next();
        if (token.text.empty()) fail(0, "the file is empty");
        std::uint64_t count = 0;
        const char* end = token.text.data() + token.text.size();
        const auto [stop, error] = std::from_chars(token.text.data(), end, count);
        if (error == std::errc::result_out_of_range)
            fail(token.line, "the object count " + quote(token.text) + " is too large");
        if (error != std::errc() || stop != end) // from_chars takes no sign for an unsigned type
            fail(token.line, "expected the object count (a non-negative integer) at the start of "
                             "the file, found " +
                                 quote(token.text));
        return count;
    }

    void readHeader() {
        claimedCount = readObjectCount();
        scene.ambient = readColourField({&ambient}, false);
    }

    // Once a few thousand objects are read, reserves room for the rest of the text at
    // the rate seen so far, plus an eighth. Growing by doubling would copy each array
    // again and again, and fault in twice the memory; a million triangles fill 300 MB.
    // The estimate rests on bytes actually in the file, never on the header's count,
    // and space reserved but never filled is address space only, not memory.
    void reserveAtTheRateSoFar() {
        const double bytesSoFar = double(tokens.pos - objectsStart);
        if (!(sizeUntil > tokens.pos) || bytesSoFar <= 0.0) return;
        const double scale = double(sizeUntil - objectsStart) / bytesSoFar * 1.125;
        const auto reserve = [scale](auto& values) {
            values.reserve(std::size_t(double(values.size()) * scale) + 16);
        };
        reserve(scene.spheres);
        reserve(scene.triangles);
        reserve(scene.lights);
    }

    void readObject() {
        constexpr std::uint64_t kEstimateAfter = 4096;
        if (objectsHere == 0) objectsStart = tokens.skipSpace();
        if (objectsHere == kEstimateAfter) reserveAtTheRateSoFar();
        ++objectsHere;
        const Token token = next();
        if (token.text.empty())
            fail(token.line, "the header says " + objects(claimedCount) +
                                 " but the file ends after " + std::to_string(objectsRead));
        if (equalsIgnoreCase(token.text, "sphere"))
            scene.spheres.push_back(readSphere());
        else if (equalsIgnoreCase(token.text, "triangle"))
            scene.triangles.push_back(readTriangle(token.line));
        else if (equalsIgnoreCase(token.text, "light"))
            scene.lights.push_back(readLight());
        else
            fail(token.line, "unknown object keyword " + quote(token.text) +
                                 " (expected 'sphere', 'triangle' or 'light')");
        ++objectsRead;
    }

    // Reads objects in file order until the header's count is reached, or until the
    // next token starts at stopAt while an object is expected: true then. The count is
    // only compared with what is read, never used to allocate: a header claiming
    // billions of objects costs nothing until they appear.
    bool readObjects() {
        while (objectsRead < claimedCount) {
            if (tokens.skipSpace() == stopAt) return true;
            readObject();
        }
        return false;
    }

    void expectEnd() {
        const Token extra = next();
        if (!extra.text.empty())
            fail(extra.line, "the header says " + objects(claimedCount) +
                                 " but more follow: " + quote(extra.text));
    }

    // A chunk read ahead: objects, however many, from its start to stopAt or the end.
    // False if cancelled before getting there.
    bool readChunk(const std::stop_token& cancel) {
        for (;;) {
            const std::size_t at = tokens.skipSpace();
            if (at == stopAt || at == tokens.text.size()) return true;
            if (cancel.stop_requested()) return false;
            readObject();
        }
    }
};

} // namespace

SceneError::SceneError(std::string fileName, int lineNumber, std::string text)
    : std::runtime_error(location(fileName, lineNumber) + "error: " + text),
      file(std::move(fileName)), line(lineNumber), message(std::move(text)) {}

namespace {

void appendWarnings(Scene& scene, const Parser& parser, int firstLine) {
    for (const Warning& warning : parser.warnings)
        scene.warnings.push_back(location(parser.file, warning.line + firstLine - 1) +
                                 "warning: " + warning.message);
}

template <typename T> void appendAll(std::vector<T>& into, const std::vector<T>& from) {
    into.insert(into.end(), from.begin(), from.end());
}

// Joins the scenes of readers that read consecutive parts of the text, in order.
Scene joinScenes(const std::vector<std::pair<Parser*, int>>& parts) {
    std::size_t spheres = 0, triangles = 0, lights = 0;
    for (const auto& [parser, firstLine] : parts) {
        spheres += parser->scene.spheres.size();
        triangles += parser->scene.triangles.size();
        lights += parser->scene.lights.size();
    }
    Scene scene = std::move(parts.front().first->scene);
    reserveExactly(scene.spheres, spheres);
    reserveExactly(scene.triangles, triangles);
    reserveExactly(scene.lights, lights);
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const auto& [parser, firstLine] = parts[i];
        if (i > 0) {
            appendAll(scene.spheres, parser->scene.spheres);
            appendAll(scene.triangles, parser->scene.triangles);
            appendAll(scene.lights, parser->scene.lights);
        }
        appendWarnings(scene, *parser, firstLine);
    }
    return scene;
}

Scene parseText(std::string_view text, const std::string& fileName,
                const std::vector<std::size_t>& starts) {
    Parser first{Tokenizer{text}, fileName};
    first.sizeUntil = text.size(); // the chunks read ahead are appended to its arrays
    std::vector<Parser> ahead;
    ahead.reserve(starts.size() - 1);
    for (std::size_t k = 1; k < starts.size(); ++k) {
        ahead.push_back(Parser{Tokenizer{text, starts[k]}, fileName});
        ahead.back().stopAt = k + 1 < starts.size() ? starts[k + 1] : kNowhere;
        ahead.back().sizeUntil = k + 1 < starts.size() ? starts[k + 1] : text.size();
    }
    std::vector<char> complete(ahead.size(), 0);
    {
        // On an exception from the first reader, the workers are told to stop and joined.
        std::vector<std::jthread> workers;
        for (std::size_t k = 0; k < ahead.size(); ++k)
            workers.emplace_back([&, k](std::stop_token cancel) {
                try {
                    complete[k] = ahead[k].readChunk(cancel);
                } catch (...) {
                    // Read again in order below, which says what is wrong.
                }
            });
        first.stopAt = starts.size() > 1 ? starts[1] : kNowhere;
        first.readHeader();
        if (!first.readObjects()) {
            first.expectEnd();
            return joinScenes({{&first, 1}});
        }
        for (std::jthread& worker : workers)
            worker.join();
    }

    // Confirm the chunks in order while the counts add up.
    std::vector<std::pair<Parser*, int>> parts{{&first, 1}};
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
    std::optional<Parser> rest;
    if (k < ahead.size()) {
        rest.emplace(Parser{Tokenizer{text, starts[k + 1], line}, fileName});
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
    if (const auto reason = scene_text::binaryReason(text))
        throw SceneError(fileName, 0, "the file is binary (" + *reason + ")");
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3); // UTF-8 byte-order mark
    return parseText(text, fileName,
                     scene_text::chunkStarts(text, options.threads, options.minChunkBytes));
}

Scene parseScene(std::string_view text, const std::string& fileName) {
    return parseScene(text, fileName, SceneParseOptions{});
}

Scene loadScene(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code error;
    // open succeeds on a directory on Linux and only the read fails; say it plainly.
    if (std::filesystem::is_directory(path, error))
        throw SceneError(name, 0, std::string("cannot open file: ") + std::strerror(EISDIR));
    const SceneFileBytes file(name);
    return parseScene(file.text(), name);
}
