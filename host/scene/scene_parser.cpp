// The grammar of the scene file (scene_parser.h): a token cursor, one function per
// object, and a message for every way a file can be wrong. Messages name the object
// and the field and say what was expected, so they can be fixed without reading this
// code.
#include "scene/scene_parser.h"

#include <charconv>
#include <cstdint>
#include <system_error>

using scene_lexer::NumberStatus;
using scene_lexer::Token;

namespace scene_parser {

struct Key {
    std::string_view text; // as written in the file, lower case
    const char* name;      // as messages name the field
};

struct Number {
    double value;
    std::string_view text; // as written, for messages
    int line;
};

namespace {

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

constexpr Key position{"pos:", "position"}, radius{"rad:", "radius"}, normal{"nor:", "normal"},
    diffuse{"dif:", "'dif:'"}, specular{"spe:", "'spe:'"}, shininess{"shi:", "shininess"},
    mirror{"mir:", "mirror share"}, color{"col:", "colour"}, ambient{"amb:", "ambient colour"};

std::string describe(const Field& field) {
    if (!field.key) return field.object ? quote(field.object) : "the object count";
    std::string text = "the ";
    if (field.object) (text += field.object) += "'s ";
    if (field.vertex > 0) (text += "vertex ") += std::to_string(field.vertex) + " ";
    return text += field.key->name;
}

} // namespace

void Reader::fail(int line, const std::string& message) const {
    throw SceneError(file, line, message);
}

void Reader::warn(int line, const std::string& message) {
    warnings.push_back({line, message});
}

Token Reader::next() {
    Token token = tokens.next();
    if (token.text.empty()) token.line = lastLine;
    lastLine = token.line;
    return token;
}

void Reader::expectKey(const Field& field) {
    if (tokens.skipKey(field.key->text)) {
        keyLine = lastLine = tokens.line;
        return;
    }
    const Token token = next();
    keyLine = token.line;
    const std::string_view key = field.key->text;
    if (equalsIgnoreCase(token.text, key)) return;
    if (token.text.size() > key.size() && equalsIgnoreCase(token.text.substr(0, key.size()), key))
        fail(token.line, "the key '" + std::string(key) +
                             "' must be separated from its numbers by whitespace, found " +
                             quote(token.text));
    std::string message = "expected '" + std::string(key) + "' after " + describe(previous) +
                          ", found " + quote(token.text);
    if (field.vertex > 1 && field.key == &position) message += " (a triangle has three vertices)";
    fail(token.line, message);
}

Number Reader::readNumber(const Field& field) {
    double value = 0.0;
    if (const std::size_t length = tokens.nextSimpleNumber(value)) {
        lastLine = tokens.line;
        return {value, tokens.text.substr(tokens.pos - length, length), tokens.line};
    }
    const Token token = next();
    const NumberStatus status = scene_lexer::parseNumber(token.text, value);
    if (status == NumberStatus::nonFinite)
        fail(token.line, "non-finite number " + quote(token.text) + " for " + describe(field));
    if (status == NumberStatus::invalid)
        fail(token.line,
             "expected a number for " + describe(field) + ", found " + quote(token.text));
    return {value, token.text, token.line};
}

// "key: number"; the caller checks the range, as it knows what the number means.
Number Reader::readScalarField(const Field& field) {
    expectKey(field);
    const Number number = readNumber(field);
    previous = field;
    return number;
}

// "key: x y z" for a position or a normal.
glm::dvec3 Reader::readVec3Field(const Field& field) {
    expectKey(field);
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = readNumber(field).value;
    previous = field;
    return v;
}

// "key: r g b". Negative is an error; above 1 is fine for lights and the ambient
// colour (bright lights) but gets a warning for dif and spe (the mix extrapolates).
glm::dvec3 Reader::readColorField(const Field& field, bool warnAboveOne) {
    expectKey(field);
    glm::dvec3 c;
    bool warned = false;
    for (int i = 0; i < 3; ++i) {
        const Number number = readNumber(field);
        if (number.value < 0.0)
            fail(number.line,
                 "negative colour value " + std::string(number.text) + " in " + describe(field));
        if (warnAboveOne && number.value > 1.0 && !warned) {
            warn(number.line,
                 describe(field) + " " + std::string(number.text) + " is above 1; used as given");
            warned = true;
        }
        c[i] = number.value;
    }
    previous = field;
    return c;
}

Material Reader::readMaterial(const char* object, int vertex) {
    Material m;
    m.diffuse = readColorField({&diffuse, object, vertex}, true);
    m.specular = readColorField({&specular, object, vertex}, true);
    const Field field{&shininess, object, vertex};
    const Number s = readScalarField(field);
    if (s.value < 0.0)
        fail(s.line, describe(field) + " must not be negative, found " + std::string(s.text));
    m.shininess = s.value;
    // The optional mirror share (docs/model.md): a material without it mirrors by its ks,
    // as in the classic format.
    if (tokens.skipKey(mirror.text)) {
        keyLine = lastLine = tokens.line;
        const Field share{&mirror, object, vertex};
        const Number number = readNumber(share);
        if (!(number.value >= 0.0 && number.value <= 1.0))
            fail(number.line,
                 describe(share) + " must be between 0 and 1, found " + std::string(number.text));
        m.mirror = number.value;
        previous = share;
    }
    return m;
}

Sphere Reader::readSphere() {
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

// Degenerate triangles are legal (docs/model.md): kept as given, with a warning.
Triangle Reader::readTriangle(int keywordLine) {
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
        warn(keywordLine, "the triangle has zero area (its vertices are collinear or coincide)");
    return triangle;
}

Light Reader::readLight() {
    Light light;
    previous = {nullptr, "light"};
    light.position = readVec3Field({&position, "light"});
    light.color = readColorField({&color, "light"}, false);
    return light;
}

// A plain non-negative decimal integer, nothing else (no sign, point or exponent).
std::uint64_t Reader::readObjectCount() {
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

void Reader::readHeader() {
    claimedCount = readObjectCount();
    scene.ambient = readColorField({&ambient}, false);
}

// Once a few thousand objects are read, reserves room for the rest of the text at
// the rate seen so far, plus an eighth. Growing by doubling would copy each array
// again and again, and fault in twice the memory; a million triangles fill 300 MB.
// The estimate rests on bytes actually in the file, never on the header's count,
// and space reserved but never filled is address space only, not memory.
void Reader::reserveAtTheRateSoFar() {
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

void Reader::readObject() {
    constexpr std::uint64_t kEstimateAfter = 4096;
    if (objectsHere == 0) objectsStart = tokens.skipSpace();
    if (objectsHere == kEstimateAfter) reserveAtTheRateSoFar();
    ++objectsHere;
    const Token token = next();
    if (token.text.empty())
        fail(token.line, "the header says " + objects(claimedCount) + " but the file ends after " +
                             std::to_string(objectsRead));
    // Each object keeps its keyword's line, counted from where this reader started
    // (joinScenes makes it the file's line).
    if (equalsIgnoreCase(token.text, "sphere")) {
        scene.spheres.push_back(readSphere());
        scene.spheres.back().line = token.line;
    } else if (equalsIgnoreCase(token.text, "triangle")) {
        scene.triangles.push_back(readTriangle(token.line));
        scene.triangles.back().line = token.line;
    } else if (equalsIgnoreCase(token.text, "light")) {
        scene.lights.push_back(readLight());
        scene.lights.back().line = token.line;
    } else
        fail(token.line, "unknown object keyword " + quote(token.text) +
                             " (expected 'sphere', 'triangle' or 'light')");
    ++objectsRead;
}

// The count is only compared with what is read, never used to allocate: a header
// claiming billions of objects costs nothing until they appear.
bool Reader::readObjects() {
    while (objectsRead < claimedCount) {
        if (tokens.skipSpace() == stopAt) return true;
        readObject();
    }
    return false;
}

void Reader::expectEnd() {
    const Token extra = next();
    if (!extra.text.empty())
        fail(extra.line,
             "the header says " + objects(claimedCount) + " but more follow: " + quote(extra.text));
}

bool Reader::readChunk(const std::stop_token& cancel) {
    for (;;) {
        const std::size_t at = tokens.skipSpace();
        if (at == stopAt || at == tokens.text.size()) return true;
        if (cancel.stop_requested()) return false;
        readObject();
    }
}

} // namespace scene_parser
