#include "model/ply_reader.h"

#include "model/polygon_triangulation.h"
#include "scene/scene_error.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <vector>

namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<PlyType> typeNamed(std::string_view name) {
    static const std::pair<std::string_view, PlyType> names[] = {
        {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
        {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
        {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
        {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
        {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
        {"float64", PlyType::Float64}};
    for (const auto& [text, type] : names)
        if (text == name) return type;
    return std::nullopt;
}

std::size_t sizeOf(PlyType type) {
    switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
        return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
        return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
        return 4;
    case PlyType::Float64:
        return 8;
    }
    return 1;
}

bool isInteger(PlyType type) {
    return type != PlyType::Float32 && type != PlyType::Float64;
}

// The largest value of an unsigned integer type, which a colour of that type is divided by.
double colourScale(PlyType type) {
    switch (type) {
    case PlyType::UInt8:
    case PlyType::Int8:
        return 255.0;
    case PlyType::UInt16:
    case PlyType::Int16:
        return 65535.0;
    case PlyType::UInt32:
    case PlyType::Int32:
        return 4294967295.0;
    default:
        return 1.0;
    }
}

// What a property is to the model.
enum class Role { Skip, X, Y, Z, NX, NY, NZ, Red, Green, Blue, Indices };

struct Property {
    std::string name;
    PlyType type = PlyType::Float32;
    std::optional<PlyType> countType; // set for a list
    Role role = Role::Skip;
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;
};

enum class Format { Ascii, LittleEndian, BigEndian };

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    std::size_t body = 0; // the first byte after end_header's line
    int lines = 0;        // the header's lines: the body's first line is lines + 1
};

std::vector<std::string_view> wordsOf(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && (line[at] == ' ' || line[at] == '\t' || line[at] == '\r'))
            ++at;
        const std::size_t start = at;
        while (at < line.size() && line[at] != ' ' && line[at] != '\t' && line[at] != '\r')
            ++at;
        if (at > start) words.push_back(line.substr(start, at - start));
    }
    return words;
}

Role roleOf(const std::string& element, const Property& property) {
    if (element == "vertex" && !property.countType) {
        static const std::pair<std::string_view, Role> roles[] = {{"x", Role::X},
                                                                  {"y", Role::Y},
                                                                  {"z", Role::Z},
                                                                  {"nx", Role::NX},
                                                                  {"ny", Role::NY},
                                                                  {"nz", Role::NZ},
                                                                  {"red", Role::Red},
                                                                  {"green", Role::Green},
                                                                  {"blue", Role::Blue},
                                                                  {"r", Role::Red},
                                                                  {"g", Role::Green},
                                                                  {"b", Role::Blue},
                                                                  {"diffuse_red", Role::Red},
                                                                  {"diffuse_green", Role::Green},
                                                                  {"diffuse_blue", Role::Blue}};
        for (const auto& [name, role] : roles)
            if (property.name == name) return role;
    }
    if ((element == "face" || element == "tristrips") && property.countType &&
        (property.name == "vertex_indices" || property.name == "vertex_index"))
        return Role::Indices;
    return Role::Skip;
}

Header readHeader(std::string_view bytes, const std::string& fileName) {
    Header header;
    std::size_t at = 0;
    bool ended = false, formatSeen = false;
    while (!ended) {
        if (at >= bytes.size())
            throw SceneError(fileName, header.lines,
                             "the file ends before the PLY header's end_header line");
        if (at > (std::size_t(1) << 20))
            throw SceneError(fileName, header.lines,
                             "the PLY header has no end_header line in its first MiB");
        const std::size_t end = std::min(bytes.find('\n', at), bytes.size());
        const std::string_view line = bytes.substr(at, end - at);
        at = end + 1;
        ++header.lines;
        const std::vector<std::string_view> words = wordsOf(line);
        auto fail = [&](const std::string& message) {
            throw SceneError(fileName, header.lines, message);
        };
        if (header.lines == 1) {
            if (words.size() != 1 || words[0] != "ply") fail("a PLY file starts with the line ply");
            continue;
        }
        if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
        if (words[0] == "end_header") {
            ended = true;
        } else if (words[0] == "format") {
            if (words.size() != 3) fail("format expects a kind and a version");
            if (words[1] == "ascii")
                header.format = Format::Ascii;
            else if (words[1] == "binary_little_endian")
                header.format = Format::LittleEndian;
            else if (words[1] == "binary_big_endian")
                header.format = Format::BigEndian;
            else
                fail("the format '" + std::string(words[1]) +
                     "' is none of ascii, binary_little_endian, binary_big_endian");
            formatSeen = true;
        } else if (words[0] == "element") {
            if (words.size() != 3) fail("element expects a name and a count");
            Element element;
            element.name = std::string(words[1]);
            const auto [end2, error] =
                std::from_chars(words[2].data(), words[2].data() + words[2].size(), element.count);
            if (error != std::errc() || end2 != words[2].data() + words[2].size())
                fail("the count of element " + element.name + " is not a whole number: '" +
                     std::string(words[2]) + "'");
            header.elements.push_back(element);
        } else if (words[0] == "property") {
            if (header.elements.empty()) fail("a property before any element");
            Property property;
            if (words.size() == 5 && words[1] == "list") {
                property.countType = typeNamed(words[2]);
                if (!property.countType || !isInteger(*property.countType))
                    fail("a list's count type must be an integer type, not '" +
                         std::string(words[2]) + "'");
                const auto type = typeNamed(words[3]);
                if (!type) fail("unknown property type '" + std::string(words[3]) + "'");
                property.type = *type;
                property.name = std::string(words[4]);
            } else if (words.size() == 3) {
                const auto type = typeNamed(words[1]);
                if (!type) fail("unknown property type '" + std::string(words[1]) + "'");
                property.type = *type;
                property.name = std::string(words[2]);
            } else {
                fail("property expects a type and a name, or list, two types and a name");
            }
            property.role = roleOf(header.elements.back().name, property);
            if (property.role == Role::Indices && !isInteger(property.type))
                property.role = Role::Skip;
            header.elements.back().properties.push_back(property);
        } else {
            fail("unknown header line '" + std::string(words[0]) + "'");
        }
    }
    if (!formatSeen) throw SceneError(fileName, 0, "the PLY header has no format line");
    header.body = std::min(at, bytes.size());
    return header;
}

// The values of the body, one after the other, binary or ASCII.
class Values {
  public:
    Values(std::string_view bytes, const Header& header, const std::string& fileName)
        : bytes_(bytes), at_(header.body), format_(header.format), line_(header.lines + 1),
          fileName_(fileName) {}

    std::size_t left() const { return bytes_.size() - at_; }
    // Where the values being read belong, for messages: instance `index` of element.
    void place(const Element& element, std::uint64_t index) {
        element_ = &element;
        index_ = index;
    }
    std::string where() const {
        return element_ ? element_->name + " " + std::to_string(index_ + 1) + " of " +
                              std::to_string(element_->count)
                        : std::string("the body");
    }
    bool ascii() const { return format_ == Format::Ascii; }
    int line() const { return ascii() ? line_ : 0; }

    double next(PlyType type) {
        if (ascii()) return nextText();
        const std::size_t size = sizeOf(type);
        if (left() < size) cutShort();
        unsigned char raw[8];
        std::memcpy(raw, bytes_.data() + at_, size);
        at_ += size;
        if (format_ == Format::BigEndian) std::reverse(raw, raw + size);
        switch (type) {
        case PlyType::Int8:
            return double(std::bit_cast<std::int8_t>(raw[0]));
        case PlyType::UInt8:
            return double(raw[0]);
        case PlyType::Int16: {
            std::int16_t v;
            std::memcpy(&v, raw, 2);
            return v;
        }
        case PlyType::UInt16: {
            std::uint16_t v;
            std::memcpy(&v, raw, 2);
            return v;
        }
        case PlyType::Int32: {
            std::int32_t v;
            std::memcpy(&v, raw, 4);
            return v;
        }
        case PlyType::UInt32: {
            std::uint32_t v;
            std::memcpy(&v, raw, 4);
            return v;
        }
        case PlyType::Float32: {
            float v;
            std::memcpy(&v, raw, 4);
            return v;
        }
        case PlyType::Float64: {
            double v;
            std::memcpy(&v, raw, 8);
            return v;
        }
        }
        return 0.0;
    }

    // In ASCII an instance is a line: what is left of the line after its properties (some
    // exporters write more values than their header declares) is read past, and counted.
    void endInstance() {
        if (!ascii()) return;
        while (at_ < bytes_.size() &&
               (bytes_[at_] == ' ' || bytes_[at_] == '\t' || bytes_[at_] == '\r'))
            ++at_;
        if (at_ < bytes_.size() && bytes_[at_] != '\n') {
            if (extraLines_++ == 0) firstExtraLine_ = line_;
            while (at_ < bytes_.size() && bytes_[at_] != '\n')
                ++at_;
        }
        if (at_ < bytes_.size()) {
            ++at_;
            ++line_;
        }
    }
    std::size_t extraLines() const { return extraLines_; }
    int firstExtraLine() const { return firstExtraLine_; }

    [[noreturn]] void fail(const std::string& message) const {
        throw SceneError(fileName_, line(), message);
    }

  private:
    [[noreturn]] void cutShort() const { fail("the file is cut short in " + where()); }

    double nextText() {
        while (at_ < bytes_.size() && (bytes_[at_] == ' ' || bytes_[at_] == '\t' ||
                                       bytes_[at_] == '\r' || bytes_[at_] == '\n')) {
            if (bytes_[at_] == '\n') ++line_;
            ++at_;
        }
        if (at_ >= bytes_.size()) cutShort();
        const char* start = bytes_.data() + at_;
        const char* end = bytes_.data() + bytes_.size();
        double value = 0.0;
        const auto [stop, error] = std::from_chars(start, end, value);
        if (error != std::errc() ||
            (stop != end && *stop != ' ' && *stop != '\t' && *stop != '\r' && *stop != '\n')) {
            const char* word = start;
            while (word != end && *word != ' ' && *word != '\t' && *word != '\r' && *word != '\n')
                ++word;
            fail("'" + std::string(start, std::min<std::size_t>(word - start, 40)) +
                 "' is not a number (in " + where() + ")");
        }
        at_ += std::size_t(stop - start);
        return value;
    }

    std::string_view bytes_;
    std::size_t at_;
    Format format_;
    int line_;
    const std::string& fileName_;
    const Element* element_ = nullptr;
    std::uint64_t index_ = 0;
    std::size_t extraLines_ = 0;
    int firstExtraLine_ = 0;
};

// The fewest bytes one instance of an element takes in the body: its scalars' sizes and its
// lists' counts in binary, a digit and a separator a value in ASCII.
std::uint64_t smallestInstance(const Element& element, bool ascii) {
    std::uint64_t bytes = 0;
    for (const Property& property : element.properties)
        bytes += ascii                ? 2
                 : property.countType ? sizeOf(*property.countType)
                                      : sizeOf(property.type);
    return std::max<std::uint64_t>(bytes, 1);
}

struct PlyReading {
    SourceModel model;
    std::vector<std::uint32_t> polygon; // the face being read
    std::size_t shortFaces = 0;         // faces of fewer than 3 corners, left out
    std::size_t fannedConcave = 0;
    bool normals = false, colours = false;
};

void addFace(PlyReading& reading, std::span<const std::uint32_t> corners) {
    SourceModel& model = reading.model;
    const std::uint32_t face = addFace(model, corners);
    auto corner = [&](std::uint32_t p) {
        SourceCorner c;
        c.position = p;
        if (reading.normals) c.normal = p;
        return c;
    };
    if (corners.size() == 3) {
        model.triangles.push_back(
            {{corner(corners[0]), corner(corners[1]), corner(corners[2])}, 0, face, 0});
        return;
    }
    std::vector<glm::dvec3> points;
    for (const std::uint32_t p : corners)
        points.push_back(model.positions[p]);
    const PolygonTriangles split = triangulatePolygon(points);
    reading.fannedConcave += split.fannedConcave ? 1 : 0;
    for (const auto& [a, b, c] : split.triangles)
        model.triangles.push_back(
            {{corner(corners[a]), corner(corners[b]), corner(corners[c])}, 0, face, 0});
}

// A strip's triangles: each three consecutive indices, every second one turned so that all
// face the same way; those with two equal corners (where strips are joined) left out.
void addStrip(PlyReading& reading, const std::vector<std::uint32_t>& strip) {
    for (std::size_t i = 2; i < strip.size(); ++i) {
        const std::uint32_t a = strip[i - 2], b = strip[i - 1], c = strip[i];
        if (a == b || b == c || a == c) continue;
        const std::array<std::uint32_t, 3> triangle = i % 2 == 0
                                                          ? std::array<std::uint32_t, 3>{a, b, c}
                                                          : std::array<std::uint32_t, 3>{b, a, c};
        addFace(reading, triangle);
    }
}

// Reads the index lists of a face or tristrips element.
void readIndices(PlyReading& reading, Values& values, const Element& element,
                 const Property& property) {
    const double count = values.next(*property.countType);
    const std::uint64_t each = values.ascii() ? 2 : sizeOf(property.type);
    if (!(count >= 0.0) || count > double(values.left() / each))
        values.fail("the file is cut short in " + values.where() + " (its list claims " +
                    std::to_string(std::llround(count)) + " values)");
    const bool strips = element.name == "tristrips";
    const std::size_t vertices = reading.model.positions.size();
    std::vector<std::uint32_t>& corners = reading.polygon;
    corners.clear();
    for (std::uint64_t k = 0; k < std::uint64_t(count); ++k) {
        const double index = values.next(property.type);
        if (strips && index == -1.0) { // a restart
            addStrip(reading, corners);
            corners.clear();
            continue;
        }
        if (!(index >= 0.0) || index >= double(vertices) || index != std::floor(index))
            values.fail("the index " + std::to_string(std::llround(index)) + " of " +
                        values.where() + " names no vertex (there are " + std::to_string(vertices) +
                        ")");
        corners.push_back(static_cast<std::uint32_t>(index));
    }
    if (strips) {
        addStrip(reading, corners);
    } else if (corners.size() < 3) {
        ++reading.shortFaces;
    } else {
        addFace(reading, corners);
    }
}

} // namespace

SourceModel readPly(std::string_view bytes, const std::string& fileName) {
    const Header header = readHeader(bytes, fileName);
    Values values(bytes, header, fileName);
    PlyReading reading;
    SourceModel& model = reading.model;
    model.materials.push_back(defaultModelMaterial());
    const Element* vertexElement = nullptr;
    for (const Element& element : header.elements) {
        if (element.count > (values.left() + 1) / smallestInstance(element, values.ascii()) ||
            element.count > 0xFFFFFFFFull)
            throw SceneError(fileName, 0,
                             "the PLY header claims " + std::to_string(element.count) + " " +
                                 element.name + " element(s), more than the " +
                                 std::to_string(bytes.size() - header.body) +
                                 " bytes after the header can hold");
        if (element.name == "vertex") vertexElement = &element;
    }
    if (vertexElement) {
        auto has = [&](Role role) {
            return std::any_of(vertexElement->properties.begin(), vertexElement->properties.end(),
                               [&](const Property& p) { return p.role == role; });
        };
        if (!has(Role::X) || !has(Role::Y) || !has(Role::Z))
            throw SceneError(fileName, 0, "the PLY vertex element has no x, y and z properties");
        reading.normals = has(Role::NX) && has(Role::NY) && has(Role::NZ);
        reading.colours = has(Role::Red) && has(Role::Green) && has(Role::Blue);
    }
    for (const Element& element : header.elements) {
        const bool vertex = &element == vertexElement;
        if (vertex) {
            model.positions.reserve(element.count);
            model.positionLines.reserve(element.count);
            if (reading.colours) model.colors.reserve(element.count);
            if (reading.normals) model.normals.reserve(element.count);
        }
        for (std::uint64_t i = 0; i < element.count; ++i) {
            glm::dvec3 position(0.0), normal(0.0), colour(0.0);
            const int line = values.line();
            values.place(element, i);
            for (const Property& property : element.properties) {
                if (property.role == Role::Indices) {
                    readIndices(reading, values, element, property);
                    continue;
                }
                if (property.countType) { // a list nobody reads: skipped value by value
                    const double count = values.next(*property.countType);
                    const std::uint64_t each = values.ascii() ? 2 : sizeOf(property.type);
                    if (!(count >= 0.0) || count > double(values.left() / each))
                        values.fail("the file is cut short in " + values.where() +
                                    " (a list claims more values than follow)");
                    for (std::uint64_t k = 0; k < std::uint64_t(count); ++k)
                        values.next(property.type);
                    continue;
                }
                const double v = values.next(property.type);
                if (property.role != Role::Skip && !std::isfinite(v))
                    values.fail("the " + property.name + " of " + values.where() +
                                " is not a finite number");
                switch (property.role) {
                case Role::X:
                    position.x = v;
                    break;
                case Role::Y:
                    position.y = v;
                    break;
                case Role::Z:
                    position.z = v;
                    break;
                case Role::NX:
                    normal.x = v;
                    break;
                case Role::NY:
                    normal.y = v;
                    break;
                case Role::NZ:
                    normal.z = v;
                    break;
                case Role::Red:
                    colour.r = v / colourScale(property.type);
                    break;
                case Role::Green:
                    colour.g = v / colourScale(property.type);
                    break;
                case Role::Blue:
                    colour.b = v / colourScale(property.type);
                    break;
                default:
                    break;
                }
            }
            values.endInstance();
            if (!vertex) continue;
            model.positions.push_back(position);
            model.positionLines.push_back(line);
            if (reading.colours) model.colors.emplace_back(glm::clamp(colour, 0.0, 1.0));
            if (reading.normals) model.normals.push_back(normal);
        }
    }
    if (model.triangles.empty())
        throw SceneError(fileName, 0, "no faces found (a face or tristrips element)");
    if (values.extraLines() > 0)
        model.warnings.push_back(sceneLocation(fileName, values.firstExtraLine()) +
                                 "warning: " + std::to_string(values.extraLines()) +
                                 " line(s) hold more values than the header's properties; the "
                                 "extra values are ignored");
    if (reading.shortFaces > 0)
        model.warnings.push_back(sceneLocation(fileName, 0) +
                                 "warning: " + std::to_string(reading.shortFaces) +
                                 " face(s) of fewer than 3 corners left out");
    if (reading.fannedConcave > 0)
        model.warnings.push_back(sceneLocation(fileName, 0) +
                                 "warning: " + std::to_string(reading.fannedConcave) +
                                 " concave face(s) not in one plane, or crossing themselves, "
                                 "split as fans from their first corner");
    return model;
}
