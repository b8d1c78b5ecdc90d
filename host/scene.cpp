// The scene file reader (SPEC.md, "Scene file"): a token cursor, one function per
// object, and a message for every way a file can be wrong. Messages name the
// object and the field and say what was expected, so they can be fixed without
// reading this code.
#include "scene.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <system_error>

namespace {

std::string location(const std::string& file, int line) {
    return line > 0 ? file + ":" + std::to_string(line) + ": " : file + ": ";
}

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
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

// Length of the well-formed UTF-8 sequence that starts with the non-ASCII byte
// text[i], or 0 (stray continuation byte, overlong form, surrogate, past U+10FFFF,
// cut short by the end of the text).
size_t utf8SequenceLength(std::string_view text, size_t i) {
    const auto lead = static_cast<unsigned char>(text[i]);
    size_t length = 0;
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
    for (size_t k = 1; k < length; ++k) {
        const auto byte = static_cast<unsigned char>(text[i + k]);
        if (byte < (k == 1 ? low : 0x80) || byte > (k == 1 ? high : 0xBF)) return 0;
    }
    return length;
}

// Why the text is not a text file at all, or nothing: a NUL, a control byte other
// than whitespace, or bytes that are not UTF-8. Caught up front so that no message
// ever quotes binary garbage.
std::optional<std::string> binaryReason(std::string_view text) {
    static const char hex[] = "0123456789abcdef";
    for (size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if ((c >= 0x20 && c < 0x7F) || isSpace(text[i])) {
            ++i;
        } else if (c == 0) {
            return "NUL byte at offset " + std::to_string(i);
        } else if (c < 0x80) {
            return std::string("control byte 0x") + hex[c >> 4] + hex[c & 15] + " at offset " +
                   std::to_string(i);
        } else if (size_t length = utf8SequenceLength(text, i)) {
            i += length;
        } else {
            return "invalid UTF-8 at offset " + std::to_string(i);
        }
    }
    return std::nullopt;
}

// from_chars reports both 1e999 and 1e-999 as out of range and leaves the value
// unset. Tell them apart by the power of ten of the leading significant digit:
// below zero the number is merely too close to zero for a double (read as zero,
// as strtod would), otherwise it is too large (non-finite).
bool isUnderflow(std::string_view number) {
    long long power = 0;
    bool afterPoint = false, significant = false;
    size_t i = 0;
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

enum class NumberStatus { ok, invalid, nonFinite };

// The whole token as a decimal number: what from_chars accepts in general format
// (-2.6748e-08, .44, 1., -0, and also nan and inf, which are then refused) plus one
// leading '+'. Hex never gets through: general format stops at the 'x', and
// anything left over makes the token invalid.
NumberStatus parseNumber(std::string_view token, double& value) {
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

// One whitespace-separated word of the file and the line it is on.
struct Token {
    std::string_view text; // empty at the end of the file
    int line = 0;
};

// Splits the text into tokens, counting lines (LF, CRLF or a lone CR ends a line).
struct Tokenizer {
    std::string_view text;
    size_t pos = 0;
    int line = 1;

    Token next() {
        while (pos < text.size() && isSpace(text[pos])) {
            const char c = text[pos++];
            if (c == '\n' || (c == '\r' && (pos == text.size() || text[pos] != '\n'))) ++line;
        }
        const size_t start = pos;
        while (pos < text.size() && !isSpace(text[pos]))
            ++pos;
        return {text.substr(start, pos - start), line};
    }
};

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

struct Parser {
    Tokenizer tokens;
    const std::string& file;
    Scene scene{};
    Field previous{}; // the field read last, for "expected X after Y"
    int lastLine = 1; // of the last token read; end-of-file errors point here
    int keyLine = 0;  // of the last key read; warnings about its field point here

    [[noreturn]] void fail(int line, const std::string& message) const {
        throw SceneError(file, line, message);
    }

    void warn(int line, const std::string& message) {
        scene.warnings.push_back(location(file, line) + "warning: " + message);
    }

    Token next() {
        Token token = tokens.next();
        if (token.text.empty()) token.line = lastLine;
        lastLine = token.line;
        return token;
    }

    void expectKey(const Field& field) {
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
        const Token token = next();
        double value = 0.0;
        const NumberStatus status = parseNumber(token.text, value);
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

    // The count is only compared with what is read, never used to allocate: a
    // header claiming billions of objects costs nothing until they appear.
    Scene parse() {
        const std::uint64_t count = readObjectCount();
        scene.ambient = readColourField({&ambient}, false);
        for (std::uint64_t i = 0; i < count; ++i) {
            const Token token = next();
            if (token.text.empty())
                fail(token.line, "the header says " + objects(count) + " but the file ends after " +
                                     std::to_string(i));
            if (equalsIgnoreCase(token.text, "sphere"))
                scene.spheres.push_back(readSphere());
            else if (equalsIgnoreCase(token.text, "triangle"))
                scene.triangles.push_back(readTriangle(token.line));
            else if (equalsIgnoreCase(token.text, "light"))
                scene.lights.push_back(readLight());
            else
                fail(token.line, "unknown object keyword " + quote(token.text) +
                                     " (expected 'sphere', 'triangle' or 'light')");
        }
        const Token extra = next();
        if (!extra.text.empty())
            fail(extra.line,
                 "the header says " + objects(count) + " but more follow: " + quote(extra.text));
        return std::move(scene);
    }
};

} // namespace

SceneError::SceneError(std::string fileName, int lineNumber, std::string text)
    : std::runtime_error(location(fileName, lineNumber) + "error: " + text),
      file(std::move(fileName)), line(lineNumber), message(std::move(text)) {}

Scene parseScene(std::string_view text, const std::string& fileName) {
    if (text.empty()) throw SceneError(fileName, 0, "the file is empty");
    if (const auto reason = binaryReason(text))
        throw SceneError(fileName, 0, "the file is binary (" + *reason + ")");
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3); // UTF-8 byte-order mark
    Parser parser{Tokenizer{text}, fileName};
    return parser.parse();
}

Scene loadScene(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code error;
    // fopen succeeds on a directory on Linux and only the read fails; say it plainly.
    if (std::filesystem::is_directory(path, error))
        throw SceneError(name, 0, std::string("cannot open file: ") + std::strerror(EISDIR));
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(name.c_str(), "rb"),
                                                               &std::fclose);
    if (!file) throw SceneError(name, 0, std::string("cannot open file: ") + std::strerror(errno));

    std::string text;
    const auto size = std::filesystem::file_size(path, error);
    if (!error) text.reserve(size); // the real size, not a claim inside the file
    char buffer[1 << 16];
    while (const size_t n = std::fread(buffer, 1, sizeof buffer, file.get()))
        text.append(buffer, n);
    if (std::ferror(file.get()))
        throw SceneError(name, 0, std::string("cannot read file: ") + std::strerror(errno));
    return parseScene(text, name);
}
