// The OBJ and MTL statements, one logical line at a time (obj_reader.h). Each message
// is the one tools/obj_to_scene.py prints for the same line, so that the two readers
// can be held to each other (tests/tools/obj_to_scene_test.py).
#include "model/obj_reader.h"

#include "model/model_paths.h"
#include "model/polygon_triangulation.h"
#include "scene/file_format.h"
#include "scene/mapped_file.h"
#include "scene/scene_error.h"
#include "scene/scene_lexer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>

namespace {

// One statement: its first line (a trailing backslash continues it on the next) and its
// words before any '#'.
struct Statement {
    int line = 0;
    std::vector<std::string_view> words;
};

// Calls onStatement for each logical line of text; LF, CRLF and a lone CR end a line.
template <typename OnStatement>
void forEachStatement(std::string_view text, OnStatement onStatement) {
    std::string joined; // a continued line, put together
    int line = 0, start = 0;
    Statement statement; // one for every line: its words' storage is reused
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find_first_of("\r\n", pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view physical = text.substr(pos, end - pos);
        pos = end;
        if (pos < text.size())
            pos += (text[pos] == '\r' && pos + 1 < text.size() && text[pos + 1] == '\n') ? 2 : 1;
        ++line;
        if (joined.empty()) start = line;
        if (!physical.empty() && physical.back() == '\\') {
            joined.append(physical.substr(0, physical.size() - 1));
            joined.push_back(' ');
            if (pos < text.size()) continue;
            physical = {};
        } else if (!joined.empty()) {
            joined.append(physical);
        }
        std::string_view logical = joined.empty() ? physical : std::string_view(joined);
        logical = logical.substr(0, logical.find('#'));
        statement.line = start;
        statement.words.clear();
        scene_lexer::Tokenizer words{logical};
        for (auto word = words.next(); !word.text.empty(); word = words.next())
            statement.words.push_back(word.text);
        if (!statement.words.empty()) onStatement(statement);
        joined.clear();
    }
}

std::string joinWords(const std::vector<std::string_view>& words, std::size_t from) {
    std::string name;
    for (std::size_t i = from; i < words.size(); ++i) {
        if (i > from) name += ' ';
        name += words[i];
    }
    return name;
}

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
                std::string_view what, std::size_t optional = 0) {
    const std::size_t given = statement.words.size() - 1;
    if (given < count || given > count + optional) {
        const std::string wanted =
            optional == 0 ? std::to_string(count)
                          : std::to_string(count) + " to " + std::to_string(count + optional);
        place.fail(std::string(what) + " expects " + wanted + " numbers, got " +
                   std::to_string(given));
    }
    Numbers values;
    for (std::size_t i = 1; i < statement.words.size(); ++i) {
        const std::string_view word = statement.words[i];
        double value = 0.0;
        const auto status = scene_lexer::parseNumber(word, value);
        if (status == scene_lexer::NumberStatus::invalid)
            place.fail(std::string(what) + ": '" + std::string(word) + "' is not a number");
        if (status == scene_lexer::NumberStatus::nonFinite)
            place.fail(std::string(what) + ": '" + std::string(word) + "' is not a finite number");
        values.values[values.count++] = value;
    }
    return values;
}

glm::dvec3 clampedColor(const Numbers& values, std::size_t first) {
    return glm::clamp(glm::dvec3(values[first], values[first + 1], values[first + 2]), 0.0, 1.0);
}

// The file name of a texture statement (map_Kd [options] name): the words after its
// options, joined by single spaces; empty when the statement names none or holds an option
// that is not MTL's (nothing is sampled yet, so such a line costs the model nothing). The
// options are the MTL format's: -blendu, -blendv, -cc, -clamp (on or off), -bm, -texres,
// -imfchan (one value), -mm (two), -o, -s, -t (one to three numbers).
std::string textureFileName(const Statement& statement) {
    const std::vector<std::string_view>& words = statement.words;
    auto isNumber = [](std::string_view word) {
        double value = 0;
        return !word.empty() &&
               scene_lexer::parseNumber(word, value) == scene_lexer::NumberStatus::ok;
    };
    std::size_t i = 1;
    while (i < words.size() && words[i].size() > 1 && words[i][0] == '-') {
        const std::string_view option = words[i];
        std::size_t values = 0, optional = 0;
        if (option == "-blendu" || option == "-blendv" || option == "-cc" || option == "-clamp" ||
            option == "-bm" || option == "-texres" || option == "-imfchan")
            values = 1;
        else if (option == "-mm")
            values = 2;
        else if (option == "-o" || option == "-s" || option == "-t")
            values = 1, optional = 2;
        else
            return {};
        ++i;
        if (i + values > words.size()) return {};
        i += values;
        for (; optional > 0 && i < words.size() && isNumber(words[i]); --optional)
            ++i;
    }
    return i < words.size() ? joinWords(words, i) : std::string();
}

// MTL's illumination model applied to a material read with it: 0 and 1 have no highlight,
// 2 a highlight and no mirror, 3 and above (reflection, glass, Fresnel: all a mirror to
// this renderer) ks as the mirror weight too, as in a scene file.
void applyIllum(Material& material, int illum) {
    if (illum <= 1) material.specular = glm::dvec3(0.0);
    material.mirror = illum >= 3 ? 1.0 : 0.0;
}

// newmtl name -> index into the model's materials, from one MTL file. A line that is wrong
// is a warning, not an error: the material it belongs to falls back to the default one
// (its other lines are not read), a line before any material is left out, and the model
// renders on.
void readMtl(const MtlFile& file, SourceModel& model, std::map<std::string, std::uint32_t>& names) {
    std::optional<std::uint32_t> current;
    std::string currentName;
    bool skipping = false; // the current material's lines are not read (one was wrong)
    bool any = false;
    std::map<std::uint32_t, int> illumOf; // applied at the end: a Ks may follow its illum
    std::set<std::pair<std::string, std::uint32_t>> unrendered; // (what, material), once each
    auto noteUnrendered = [&](const Statement& statement) {
        if (!current) return;
        const std::string_view keyword = statement.words[0];
        auto value = [&](std::size_t i) {
            return i < statement.words.size()
                       ? std::strtod(std::string(statement.words[i]).c_str(), nullptr)
                       : 0.0;
        };
        std::string what;
        if (keyword == "map_Kd") return; // sampled (model/texture_files.h)
        if ((keyword == "d" && statement.words.size() > 1 && value(1) < 1.0) ||
            (keyword == "Tr" && value(1) > 0.0))
            what = "transparency (d, Tr)";
        else if (keyword.starts_with("map_") || keyword == "bump" || keyword == "disp" ||
                 keyword == "decal" || keyword == "refl" || keyword == "norm")
            what = "other maps (bump, map_Ks, ...)";
        if (!what.empty() && unrendered.insert({what, *current}).second) ++model.notRendered[what];
    };
    forEachStatement(*file.text, [&](const Statement& statement) {
        const Place place{file.path, statement.line};
        const std::string_view keyword = statement.words[0];
        if (keyword != "newmtl" && skipping) return;
        noteUnrendered(statement);
        try {
            if (keyword == "newmtl") {
                current.reset();
                skipping = false;
                if (statement.words.size() < 2) {
                    skipping = true; // its lines belong to no material
                    place.fail("newmtl needs a name");
                }
                current = static_cast<std::uint32_t>(model.materials.size());
                currentName = joinWords(statement.words, 1);
                model.materials.push_back(defaultModelMaterial());
                names[currentName] = *current;
                any = true;
            } else if (keyword == "Ke") {
                if (!current) place.fail("Ke before any newmtl");
                Numbers rgb = numbers(place, statement, 1, "Ke", 2);
                if (rgb.size() == 2) place.fail("Ke expects 1 or 3 numbers, got 2");
                if (rgb.size() == 1) rgb = Numbers{{rgb[0], rgb[0], rgb[0]}, 3};
                model.materials[*current].emission =
                    glm::max(glm::dvec3(rgb[0], rgb[1], rgb[2]), glm::dvec3(0.0));
            } else if (keyword == "Kd" || keyword == "Ks") {
                const std::string name(keyword);
                if (!current) place.fail(name + " before any newmtl");
                if (statement.words.size() > 1 &&
                    (statement.words[1] == "spectral" || statement.words[1] == "xyz"))
                    place.fail(name + " " + std::string(statement.words[1]) +
                               " colours are not supported; use r g b");
                Numbers rgb = numbers(place, statement, 1, name, 2);
                if (rgb.size() == 2) place.fail(name + " expects 1 or 3 numbers, got 2");
                if (rgb.size() == 1) rgb = Numbers{{rgb[0], rgb[0], rgb[0]}, 3};
                Material& material = model.materials[*current].phong;
                (keyword == "Kd" ? material.diffuse : material.specular) = clampedColor(rgb, 0);
            } else if (keyword == "Ns") {
                if (!current) place.fail("Ns before any newmtl");
                model.materials[*current].phong.shininess = std::clamp(
                    numbers(place, statement, 1, "Ns")[0], kMinModelShininess, kMaxModelShininess);
            } else if (keyword == "illum") {
                if (!current) place.fail("illum before any newmtl");
                const double illum = numbers(place, statement, 1, "illum")[0];
                if (illum != std::floor(illum) || illum < 0 || illum > 10)
                    place.fail("illum expects an illumination model, a whole number 0 to 10, "
                               "got " +
                               std::string(statement.words[1]));
                illumOf[*current] = static_cast<int>(illum);
            } else if (keyword == "map_Kd" && current) {
                const std::string texture = textureFileName(statement);
                model.materials[*current].diffuseTexture =
                    texture.empty() ? texture : besideFile(file.path, texture);
            }
            // Ka, d, Tr, Ni, other maps: nothing in this renderer's model uses them.
        } catch (const SceneError& error) {
            std::string consequence = "; the line is left out";
            if (current) {
                illumOf.erase(*current);
                model.materials[*current] = defaultModelMaterial();
                skipping = true;
                consequence = "; material '" + currentName + "' is the default one";
            } else if (skipping) {
                consequence = "; the lines up to the next newmtl are left out";
            }
            model.warnings.push_back(sceneLocation(error.file, error.line) +
                                     "warning: " + error.message + consequence);
        }
    });
    for (const auto& [material, illum] : illumOf)
        applyIllum(model.materials[material].phong, illum);
    if (!any) model.warnings.push_back(file.path + ": warning: no materials (newmtl) found");
}

// Whether a word is a whole number as OBJ indices are written: a sign, then digits.
bool isWholeNumber(std::string_view word) {
    if (!word.empty() && (word[0] == '+' || word[0] == '-')) word.remove_prefix(1);
    return !word.empty() &&
           std::all_of(word.begin(), word.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// An OBJ index (1-based, or negative: counted back from the last so far) made 0-based.
std::uint32_t resolveIndex(const Place& place, std::string_view word, std::size_t count,
                           std::string_view what) {
    if (!isWholeNumber(word))
        place.fail(std::string(what) + " index '" + std::string(word) + "' is not a whole number");
    const std::string_view digits = word[0] == '+' ? word.substr(1) : word;
    long long index = 0;
    const bool huge = std::from_chars(digits.data(), digits.data() + digits.size(), index).ec !=
                      std::errc(); // out of range of 64 bits: out of range of any model too
    if (!huge && index == 0)
        place.fail(std::string(what) + " index 0: OBJ indices start at 1 (or -1 for the last)");
    const long long resolved = index > 0 ? index - 1 : static_cast<long long>(count) + index;
    if (huge || resolved < 0 || resolved >= static_cast<long long>(count))
        place.fail(std::string(what) + " index " +
                   (huge ? std::string(digits) : std::to_string(index)) +
                   " is out of range: " + std::to_string(count) + " " +
                   (what == "vertex"   ? "vertex positions"
                    : what == "normal" ? "normals"
                                       : "texture coordinates") +
                   " defined so far");
    return static_cast<std::uint32_t>(resolved);
}

SourceCorner parseCorner(const Place& place, std::string_view word, const SourceModel& model) {
    std::array<std::string_view, 3> parts; // v, vt, vn: a fourth part is an error below
    std::size_t partCount = 0;
    for (std::size_t from = 0;;) {
        const std::size_t slash = word.find('/', from);
        if (partCount == parts.size()) {
            partCount = parts.size() + 1;
            break;
        }
        parts[partCount++] =
            word.substr(from, slash == std::string_view::npos ? slash : slash - from);
        if (slash == std::string_view::npos) break;
        from = slash + 1;
    }
    if (partCount > 3 || parts[0].empty())
        place.fail("face corner '" + std::string(word) + "' is not v, v/vt, v/vt/vn or v//vn");
    SourceCorner corner;
    corner.position = resolveIndex(place, parts[0], model.positions.size(), "vertex");
    if (partCount >= 2 && !parts[1].empty())
        corner.texcoord =
            resolveIndex(place, parts[1], model.texcoords.size(), "texture coordinate");
    if (partCount == 3 && !parts[2].empty())
        corner.normal = resolveIndex(place, parts[2], model.normals.size(), "normal");
    return corner;
}

} // namespace

SourceModel parseObj(std::string_view text, const std::string& fileName,
                     const MtlLookup& lookUpMtl) {
    if (const auto format = otherFileFormat(text))
        throw SceneError(fileName, 0,
                         otherFormatMessage(*format, fileName, ExpectedFile::SourceModel));
    if (const auto reason = scene_lexer::binaryReason(text, scene_lexer::TextEncoding::AnyBytes))
        throw SceneError(fileName, 0, "not an OBJ file: it is binary (" + *reason + ")");
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3); // UTF-8 byte-order mark
    SourceModel model;
    model.materials.push_back(defaultModelMaterial());
    std::map<std::string, std::uint32_t> names;
    std::uint32_t material = 0;
    std::set<std::string, std::less<>> ignored;
    // Libraries not found, and the faces whose material was to come from one: one warning
    // at the end says both, in place of one for each usemtl.
    std::vector<std::string> missingLibraries;
    int missingLine = 0;
    bool fellBack = false; // the current usemtl names a material no library defines
    std::size_t facesFellBack = 0;
    std::size_t fannedConcave = 0; // concave faces that could not be clipped
    int firstFannedLine = 0;
    std::vector<SourceCorner> corners; // a face's, its storage reused from face to face
    forEachStatement(text, [&](const Statement& statement) {
        const Place place{fileName, statement.line};
        const std::string_view keyword = statement.words[0];
        auto at = [&] { return sceneLocation(fileName, statement.line); };
        if (keyword == "v") {
            const Numbers values = numbers(place, statement, 3, "v", 4);
            if (values.size() == 5)
                place.fail("v expects 3, 4, 6 or 7 numbers (x y z [w], or x y z r g b), got 5");
            model.positions.emplace_back(values[0], values[1], values[2]);
            model.positionLines.push_back(statement.line);
            // x y z [w], or x y z r g b with a colour per vertex.
            model.colors.push_back(values.size() >= 6 ? std::optional(clampedColor(values, 3))
                                                      : std::nullopt);
        } else if (keyword == "vn") {
            const Numbers values = numbers(place, statement, 3, "vn");
            model.normals.emplace_back(values[0], values[1], values[2]);
        } else if (keyword == "vt") {
            const Numbers values = numbers(place, statement, 1, "vt", 2);
            model.texcoords.emplace_back(values[0], values.size() > 1 ? values[1] : 0.0);
        } else if (keyword == "f") {
            const std::size_t count = statement.words.size() - 1;
            if (count < 3)
                place.fail("a face needs at least 3 corners, got " + std::to_string(count));
            corners.clear();
            for (std::size_t i = 1; i <= count; ++i)
                corners.push_back(parseCorner(place, statement.words[i], model));
            for (const SourceCorner& corner : corners)
                model.facePositions.push_back(corner.position);
            model.faceStarts.push_back(model.facePositions.size());
            const auto face = static_cast<std::uint32_t>(faceCount(model) - 1);
            facesFellBack += fellBack ? 1 : 0;
            if (corners.size() == 3) { // the common case, without a polygon's work
                model.triangles.push_back(
                    {{corners[0], corners[1], corners[2]}, material, face, statement.line});
                return;
            }
            std::vector<glm::dvec3> points;
            for (const SourceCorner& corner : corners)
                points.push_back(model.positions[corner.position]);
            const PolygonTriangles split = triangulatePolygon(points);
            if (split.fannedConcave && fannedConcave++ == 0) firstFannedLine = statement.line;
            for (const auto& [a, b, c] : split.triangles)
                model.triangles.push_back(
                    {{corners[a], corners[b], corners[c]}, material, face, statement.line});
        } else if (keyword == "mtllib") {
            for (std::size_t i = 1; i < statement.words.size(); ++i) {
                const MtlFile library = lookUpMtl(std::string(statement.words[i]));
                if (library.text) {
                    readMtl(library, model, names);
                } else {
                    if (missingLibraries.empty()) missingLine = statement.line;
                    missingLibraries.push_back(library.path);
                }
            }
        } else if (keyword == "usemtl") {
            const std::string name = joinWords(statement.words, 1);
            const auto found = names.find(name);
            material = found == names.end() ? 0 : found->second;
            fellBack = found == names.end() && !missingLibraries.empty();
            if (found == names.end() && missingLibraries.empty())
                model.warnings.push_back(at() + "warning: unknown material '" + name +
                                         "'; default material used");
        } else if (keyword == "vp" || keyword == "o" || keyword == "g" || keyword == "s") {
            // parameter-space vertices, object and group names, smoothing groups
        } else if (ignored.insert(std::string(keyword)).second) {
            model.warnings.push_back(at() + "warning: '" + std::string(keyword) +
                                     "' statements are ignored");
        }
    });
    if (model.triangles.empty()) throw SceneError(fileName, 0, "no faces (f) found");
    if (fannedConcave > 0)
        model.warnings.push_back(sceneLocation(fileName, firstFannedLine) +
                                 "warning: " + std::to_string(fannedConcave) +
                                 " concave face(s) not in one plane, or crossing themselves, "
                                 "split as fans from their first corner");
    if (!missingLibraries.empty()) {
        std::string libraries;
        for (std::size_t i = 0; i < missingLibraries.size(); ++i)
            libraries += (i == 0                             ? ""
                          : i + 1 == missingLibraries.size() ? " and "
                                                             : ", ") +
                         missingLibraries[i];
        model.warnings.push_back(sceneLocation(fileName, missingLine) + "warning: material " +
                                 (missingLibraries.size() == 1 ? "library " : "libraries ") +
                                 libraries + " not found; " + std::to_string(facesFellBack) +
                                 " of " + std::to_string(faceCount(model)) +
                                 " faces use the default material");
    }
    return model;
}

SourceModel readObjFile(const std::filesystem::path& path, std::string_view text) {
    const std::string name = path.string();
    std::error_code error;
    const std::string folder = directoryOf(name);
    return parseObj(text, name, [&](const std::string& library) {
        MtlFile mtl{folder.empty() ? library : (std::filesystem::path(folder) / library).string(),
                    std::nullopt};
        if (!std::filesystem::exists(mtl.path, error)) return mtl;
        // A file the model names is read only when it is a file, and not beyond a size no
        // material library has: a device (mtllib /dev/zero) would be read without end.
        if (!std::filesystem::is_regular_file(mtl.path, error))
            throw SceneError(mtl.path, 0,
                             "not a regular file (a device, a pipe or a folder): a material "
                             "library must be a file");
        if (const std::uintmax_t size = std::filesystem::file_size(mtl.path, error);
            !error && size > kMaxMtlBytes)
            throw SceneError(mtl.path, 0,
                             "the file holds " + std::to_string(size) +
                                 " bytes, more than a material library may (" +
                                 std::to_string(kMaxMtlBytes >> 20) + " MiB)");
        const MappedFile mtlFile(mtl.path); // an unreadable library is an error, as the OBJ is
        mtl.text = std::string(mtlFile.text());
        return mtl;
    });
}
