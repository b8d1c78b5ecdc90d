#include "model/stl_reader.h"

#include "model/shared_positions.h"
#include "scene/file_format.h"
#include "scene/scene_error.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace {

void addTriangle(SourceModel& model, const std::uint32_t corners[3], int line) {
    const std::uint32_t face = addFace(model, std::span<const std::uint32_t>(corners, 3));
    auto corner = [](std::uint32_t position) {
        return SourceCorner{position, kNoNormal, kNoTexcoord};
    };
    model.triangles.push_back(
        {{corner(corners[0]), corner(corners[1]), corner(corners[2])}, 0, face, line});
}

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

void readBinary(std::string_view bytes, const std::string& fileName, SourceModel& model) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (84 + 50 * std::uint64_t(count) != bytes.size())
        throw SceneError(fileName, 0,
                         "a binary STL file holds 84 bytes and 50 a triangle: this one's header "
                         "claims " +
                             std::to_string(count) + " triangle(s), and it has " +
                             std::to_string(bytes.size()) + " bytes");
    SharedPositions shared(model, count / 2);
    model.positions.reserve(count / 2);
    model.triangles.reserve(count);
    for (std::uint32_t t = 0; t < count; ++t) {
        const char* record = bytes.data() + 84 + 50 * std::size_t(t) + 12; // after the normal
        std::uint32_t corners[3];
        for (int k = 0; k < 3; ++k) {
            float xyz[3];
            std::memcpy(xyz, record + 12 * k, 12);
            if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
                throw SceneError(fileName, 0,
                                 "corner " + std::to_string(k + 1) + " of triangle " +
                                     std::to_string(t + 1) + " is not a finite position");
            corners[k] = shared.add(glm::vec3(xyz[0], xyz[1], xyz[2]), std::nullopt, 0);
        }
        addTriangle(model, corners, 0);
    }
}

void readText(std::string_view bytes, const std::string& fileName, SourceModel& model) {
    SharedPositions shared(model, 1024);
    std::size_t at = 0;
    int line = 1;
    std::uint32_t corners[3];
    int corner = 0;
    int facetLine = 0;
    auto word = [&]() -> std::string_view {
        while (at < bytes.size() && isSpace(bytes[at])) {
            if (bytes[at] == '\n') ++line;
            ++at;
        }
        const std::size_t start = at;
        while (at < bytes.size() && !isSpace(bytes[at]))
            ++at;
        return bytes.substr(start, at - start);
    };
    for (std::string_view w = word(); !w.empty(); w = word()) {
        if (w == "facet") {
            if (corner != 0)
                throw SceneError(fileName, line,
                                 "a facet begins before the one at line " +
                                     std::to_string(facetLine) + " has 3 vertices");
            facetLine = line;
        } else if (w == "vertex") {
            float xyz[3];
            for (float& value : xyz) {
                const std::string_view number = word();
                if (number.empty())
                    throw SceneError(fileName, facetLine,
                                     "the file is cut short inside this facet");
                const auto [end, error] =
                    std::from_chars(number.data(), number.data() + number.size(), value);
                if (error != std::errc() || end != number.data() + number.size() ||
                    !std::isfinite(value))
                    throw SceneError(fileName, line,
                                     "vertex expects 3 finite numbers, got '" +
                                         std::string(number.substr(0, 40)) + "'");
            }
            if (corner == 3) throw SceneError(fileName, line, "a facet of more than 3 vertices");
            corners[corner++] = shared.add(glm::vec3(xyz[0], xyz[1], xyz[2]), std::nullopt, line);
        } else if (w == "endfacet" || w == "endloop") {
            if (w == "endfacet") {
                if (corner != 3)
                    throw SceneError(fileName, line,
                                     "a facet of " + std::to_string(corner) +
                                         " vertices (3 expected)");
                addTriangle(model, corners, facetLine);
                corner = 0;
            }
        }
        // solid, its name, normal, outer, loop, endsolid and the facet normal's numbers are
        // read past.
    }
    if (corner != 0)
        throw SceneError(fileName, facetLine, "the file is cut short inside this facet");
}

} // namespace

SourceModel readStl(std::string_view bytes, const std::string& fileName) {
    SourceModel model;
    model.materials.push_back(defaultModelMaterial());
    // A binary file whose size adds up is binary even when its header starts with "solid"
    // (as some CAD exporters write it).
    const bool text = !isBinaryStl(bytes) && bytes.substr(0, 5) == "solid" &&
                      bytes.substr(0, 1024).find("facet") != std::string_view::npos;
    if (!text && bytes.size() < 84)
        throw SceneError(fileName, 0,
                         "neither an ASCII STL file (solid ... facet) nor a binary one (84 "
                         "bytes and 50 a triangle): it has " +
                             std::to_string(bytes.size()) + " bytes");
    if (text)
        readText(bytes, fileName, model);
    else
        readBinary(bytes, fileName, model);
    if (model.triangles.empty()) throw SceneError(fileName, 0, "no facets found");
    return model;
}
