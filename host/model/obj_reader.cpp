// An OBJ file in four steps (obj_reader.h), the first and the third on all threads, a few
// chunks of the text each (objChunkStarts):
//   1. each chunk's survey: is it text, how many of each thing it makes, its mtllib and usemtl;
//   2. the model's arrays sized to the sums, and the material statements replayed in file
//      order: the libraries read, each usemtl's material known, their warnings said;
//   3. each chunk read into its place in the arrays (obj_fill.h);
//   4. the polygons split, once every position is there.
// The first error in file order wins: a chunk's, else the replay's.
#include "model/obj_reader.h"

#include "base/parallel.h"
#include "base/populated_memory.h"
#include "base/release.h"
#include "model/model_paths.h"
#include "model/obj_fill.h"
#include "model/obj_survey.h"
#include "scene/file_format.h"
#include "scene/mapped_file.h"
#include "scene/scene_error.h"
#include "scene/scene_lexer.h"

#include <algorithm>
#include <exception>
#include <map>
#include <optional>
#include <set>

namespace {

// What step 2 learns from the surveys: each chunk's materials, and the libraries missing.
struct MaterialReplay {
    std::vector<ObjChunkMaterials> chunks;
    std::exception_ptr error; // reading a library failed, at errorLine: nothing after it is read
    int errorLine = 0;
    // Libraries not found, and the faces whose material was to come from one: one warning
    // at the end says both, in place of one for each usemtl.
    std::vector<std::string> missingLibraries;
    int missingLine = 0;
    std::size_t facesFellBack = 0;
};

MaterialReplay replayMaterials(const std::vector<ObjChunkSurvey>& surveys,
                               const std::vector<ObjChunkPlace>& places,
                               const std::string& fileName, const MtlLookup& lookUpMtl,
                               SourceModel& model) {
    MaterialReplay replay;
    replay.chunks.resize(surveys.size());
    std::map<std::string, std::uint32_t> names;
    std::set<std::string, std::less<>> ignored;
    std::uint32_t material = 0;
    bool fellBack = false;      // the current usemtl names a material no library defines
    std::size_t fellBackAt = 0; // the face from which it does
    std::size_t facesAt = 0;    // of the event being replayed
    for (std::size_t k = 0; k < surveys.size(); ++k) {
        replay.chunks[k].atStart = material;
        for (const ObjEvent& event : surveys[k].events) {
            const int line = places[k].firstLine + event.line - 1;
            facesAt = places[k].faces + event.facesBefore;
            const std::string at = sceneLocation(fileName, line);
            if (event.kind == ObjKeyword::mtllib) {
                for (const std::string& name : event.words) {
                    try {
                        const MtlFile library = lookUpMtl(name);
                        if (library.text) {
                            readMtl(library, model, names);
                        } else {
                            if (replay.missingLibraries.empty()) replay.missingLine = line;
                            replay.missingLibraries.push_back(library.path);
                        }
                    } catch (...) {
                        replay.error = std::current_exception();
                        replay.errorLine = line;
                        return replay;
                    }
                }
            } else if (event.kind == ObjKeyword::usemtl) {
                const std::string& name = event.words[0];
                const auto found = names.find(name);
                material = found == names.end() ? 0 : found->second;
                if (fellBack) replay.facesFellBack += facesAt - fellBackAt;
                fellBack = found == names.end() && !replay.missingLibraries.empty();
                fellBackAt = facesAt;
                if (found == names.end() && replay.missingLibraries.empty())
                    model.warnings.push_back(at + "warning: unknown material '" + name +
                                             "'; default material used");
                replay.chunks[k].usemtl.push_back(material);
            } else if (ignored.insert(event.words[0]).second) {
                model.warnings.push_back(at + "warning: '" + event.words[0] +
                                         "' statements are ignored");
            }
        }
    }
    if (fellBack) replay.facesFellBack += places.back().faces - fellBackAt;
    return replay;
}

// Every array step 3 writes, at the sizes the surveys add up to, their pages mapped on all
// threads; the faces' own arrays only when some face is not a triangle.
void sizeArrays(SourceModel& model, const ObjChunkPlace& total, bool onlyTriangles) {
    resizePopulated(model.positions, total.positions);
    resizePopulated(model.positionLines, total.positions);
    resizePopulated(model.normals, total.normals);
    resizePopulated(model.texcoords, total.texcoords);
    if (onlyTriangles) {
        model.triangles.makeFacesTheTriangles();
    } else {
        resizePopulated(model.facePositions, total.facePositions);
        resizePopulated(model.faceStarts, total.faces + 1);
    }
    // A corner may name a normal (texture coordinates) only when the file has some.
    model.triangles.resize(total.triangles, total.normals > 0, total.texcoords > 0);
}

ObjChunkPlace operator+(ObjChunkPlace place, const ObjChunkSurvey& survey) {
    place.firstLine += survey.lines;
    place.positions += survey.positions;
    place.normals += survey.normals;
    place.texcoords += survey.texcoords;
    place.faces += survey.faces;
    place.facePositions += survey.facePositions;
    place.triangles += survey.triangles;
    return place;
}

std::string listed(const std::vector<std::string>& names) {
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i)
        list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return list;
}

} // namespace

SourceModel parseObj(std::string_view text, const std::string& fileName, const MtlLookup& lookUpMtl,
                     const ObjParseOptions& options) {
    if (const auto format = otherFileFormat(text))
        throw SceneError(fileName, 0,
                         otherFormatMessage(*format, fileName, ExpectedFile::SourceModel));
    const std::size_t bom = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0; // UTF-8 byte-order mark
    text.remove_prefix(bom);
    const std::vector<std::size_t> starts =
        objChunkStarts(text, options.chunks, options.minChunkBytes);
    const std::size_t chunks = starts.size();
    auto chunkText = [&](std::size_t k) {
        return text.substr(starts[k], (k + 1 < chunks ? starts[k + 1] : text.size()) - starts[k]);
    };

    // Each chunk is checked for binary bytes (its offsets made the file's), then surveyed;
    // the first binary chunk's report is the file's.
    PhaseProgress progress("Reading " + fileName, 2 * text.size()); // surveyed, then read
    std::vector<ObjChunkSurvey> surveys(chunks);
    std::vector<std::optional<std::string>> binary(chunks);
    parallelFor(
        chunks,
        [&](std::size_t k) {
            binary[k] = scene_lexer::binaryReason(chunkText(k), scene_lexer::TextEncoding::AnyBytes,
                                                  bom + starts[k]);
            if (!binary[k]) surveys[k] = surveyObjChunk(chunkText(k), &progress);
        },
        0);
    for (const std::optional<std::string>& reason : binary)
        if (reason)
            throw SceneError(fileName, 0, "not an OBJ file: it is binary (" + *reason + ")");
    std::vector<ObjChunkPlace> places{ObjChunkPlace{}};
    for (const ObjChunkSurvey& survey : surveys)
        places.push_back(places.back() + survey);
    if (options.capacity)
        checkTriangleCapacity(*options.capacity, places.back().triangles, fileName);

    SourceModel model;
    model.materials.push_back(defaultModelMaterial());
    const bool onlyTriangles = std::all_of(surveys.begin(), surveys.end(),
                                           [](const ObjChunkSurvey& s) { return s.polygons == 0; });
    sizeArrays(model, places.back(), onlyTriangles);
    const MaterialReplay replay = replayMaterials(surveys, places, fileName, lookUpMtl, model);
    surveys.clear();

    std::vector<ObjChunkResult> read(chunks);
    parallelFor(
        chunks,
        [&](std::size_t k) {
            read[k] = fillObjChunk(chunkText(k), fileName, places[k], places[k + 1],
                                   replay.chunks[k], model, &progress);
        },
        0);
    for (const ObjChunkResult& chunk : read)
        if (chunk.error && (!replay.error || chunk.error->line < replay.errorLine))
            throw *chunk.error;
    if (replay.error) std::rethrow_exception(replay.error);
    const bool anyColor = std::any_of(read.begin(), read.end(), [](const ObjChunkResult& chunk) {
        return !chunk.colors.empty();
    });
    if (anyColor) {
        resizePopulated(model.colors, model.positions.size());
        parallelFor(
            chunks,
            [&](std::size_t k) {
                for (const auto& [position, color] : read[k].colors)
                    model.colors[position] = color;
                release(read[k].colors);
            },
            0);
    }
    if (model.triangles.empty()) throw SceneError(fileName, 0, "no faces (f) found");

    std::vector<FannedConcave> fanned(chunks);
    parallelFor(
        chunks, [&](std::size_t k) { fanned[k] = splitObjPolygons(read[k], model); }, 0);
    FannedConcave allFanned;
    for (const FannedConcave& chunk : fanned) {
        if (chunk.count > 0 && allFanned.count == 0) allFanned.firstLine = chunk.firstLine;
        allFanned.count += chunk.count;
    }
    if (allFanned.count > 0)
        model.warnings.push_back(sceneLocation(fileName, allFanned.firstLine) +
                                 "warning: " + std::to_string(allFanned.count) +
                                 " concave face(s) not in one plane, or crossing themselves, "
                                 "split as fans from their first corner");
    if (!replay.missingLibraries.empty())
        model.warnings.push_back(
            sceneLocation(fileName, replay.missingLine) + "warning: material " +
            (replay.missingLibraries.size() == 1 ? "library " : "libraries ") +
            listed(replay.missingLibraries) + " not found; " +
            std::to_string(replay.facesFellBack) + " of " + std::to_string(faceCount(model)) +
            " faces use the default material");
    return model;
}

SourceModel readObjFile(const std::filesystem::path& path, std::string_view text,
                        const SceneCapacity* capacity) {
    const std::string name = path.string();
    std::error_code error;
    const std::string folder = directoryOf(name);
    return parseObj(
        text, name,
        [&](const std::string& library) {
            MtlFile mtl{folder.empty() ? library
                                       : (std::filesystem::path(folder) / library).string(),
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
        },
        ObjParseOptions{.capacity = capacity});
}
