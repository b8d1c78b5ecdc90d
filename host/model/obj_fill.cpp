#include "model/obj_fill.h"

#include "model/obj_statements.h"
#include "model/obj_survey.h"
#include "model/polygon_triangulation.h"
#include "scene/scene_lexer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <stdexcept>

using scene_lexer::isSpace;

namespace {

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

// The positions, normals and texture coordinates defined before a statement.
struct Counts {
    std::size_t positions = 0, normals = 0, texcoords = 0;
};

SourceCorner parseCorner(const Place& place, std::string_view word, const Counts& counts) {
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
    corner.position = resolveIndex(place, parts[0], counts.positions, "vertex");
    if (partCount >= 2 && !parts[1].empty())
        corner.texcoord = resolveIndex(place, parts[1], counts.texcoords, "texture coordinate");
    if (partCount == 3 && !parts[2].empty())
        corner.normal = resolveIndex(place, parts[2], counts.normals, "normal");
    return corner;
}

// An index at p of at most 9 digits, with an optional '-', that resolves (resolveIndex)
// among `count`; false for anything else, which resolveIndex then reads.
bool simpleIndex(const char*& p, const char* end, std::size_t count, std::uint32_t& index) {
    const bool negative = p != end && *p == '-';
    if (negative) ++p;
    const char* const digits = p;
    std::uint64_t value = 0;
    for (; p != end && *p >= '0' && *p <= '9'; ++p)
        value = value * 10 + std::uint64_t(*p - '0');
    if (p == digits || p - digits > 9 || value == 0 || value > count) return false;
    index = static_cast<std::uint32_t>(negative ? count - value : value - 1);
    return true;
}

// The statements of one chunk, written into the model's arrays.
class ChunkReader {
  public:
    ChunkReader(const std::string& fileName, const ObjChunkPlace& place, const ObjChunkPlace& end,
                const ObjChunkMaterials& materials, SourceModel& model, ObjChunkResult& result)
        : fileName_(fileName), next_(place), end_(end), materials_(materials), model_(model),
          result_(result), material_(materials.atStart) {}

    void read(const LogicalLine& logical) {
        const std::string_view text = logical.text;
        switch (leadingKeyword(text).value_or(ObjKeyword::ignored)) {
        case ObjKeyword::position:
            if (simpleNumbers(text, 1, numbers_) &&
                (numbers_.size() == 3 || numbers_.size() == 4 || numbers_.size() >= 6))
                return addPosition(logical.line);
            break;
        case ObjKeyword::face:
            if (simpleFace(text)) return addFace(logical.line);
            break;
        case ObjKeyword::normal:
            if (simpleNumbers(text, 2, numbers_) && numbers_.size() == 3) return addNormal();
            break;
        case ObjKeyword::texcoord:
            if (simpleNumbers(text, 2, numbers_) && numbers_.size() >= 1 && numbers_.size() <= 3)
                return addTexcoord();
            break;
        default: // the general reading below
            break;
        }
        splitStatement(logical, statement_);
        if (!statement_.words.empty()) readStatement();
    }

  private:
    // Any statement, each wrong one a SceneError: the same model as read() makes.
    void readStatement() {
        const Place place{fileName_, statement_.line};
        switch (objKeyword(statement_.words[0])) {
        case ObjKeyword::position:
            numbers_ = numbers(place, statement_, 3, "v", 4);
            if (numbers_.size() == 5)
                place.fail("v expects 3, 4, 6 or 7 numbers (x y z [w], or x y z r g b), got 5");
            return addPosition(statement_.line);
        case ObjKeyword::normal:
            numbers_ = numbers(place, statement_, 3, "vn");
            return addNormal();
        case ObjKeyword::texcoord:
            numbers_ = numbers(place, statement_, 1, "vt", 2);
            return addTexcoord();
        case ObjKeyword::face: {
            const std::size_t count = statement_.words.size() - 1;
            if (count < 3)
                place.fail("a face needs at least 3 corners, got " + std::to_string(count));
            corners_.clear();
            const Counts counts{next_.positions, next_.normals, next_.texcoords};
            for (std::size_t i = 1; i <= count; ++i)
                corners_.push_back(parseCorner(place, statement_.words[i], counts));
            return addFace(statement_.line);
        }
        case ObjKeyword::usemtl:
            material_ = usemtlSeen_ < materials_.usemtl.size() ? materials_.usemtl[usemtlSeen_] : 0;
            ++usemtlSeen_;
            return;
        case ObjKeyword::mtllib:  // read before this pass, in file order
        case ObjKeyword::skipped: // parameter-space vertices, object and group names, smoothing
        case ObjKeyword::ignored: // said once, before this pass
            return;
        }
    }

    // A face whose corners are all simpleIndex's, into corners_.
    bool simpleFace(std::string_view text) {
        corners_.clear();
        const char* p = text.data() + 1;
        const char* const end = text.data() + text.size();
        for (;;) {
            while (p != end && isSpace(*p))
                ++p;
            if (p == end) break;
            SourceCorner corner;
            if (!simpleIndex(p, end, next_.positions, corner.position)) return false;
            if (p != end && *p == '/') {
                if (++p != end && *p != '/' && !isSpace(*p) &&
                    !simpleIndex(p, end, next_.texcoords, corner.texcoord))
                    return false;
                if (p != end && *p == '/') {
                    std::uint32_t normal = 0;
                    if (++p != end && !isSpace(*p)) {
                        if (!simpleIndex(p, end, next_.normals, normal)) return false;
                        corner.normal = normal;
                    }
                }
            }
            if (p != end && !isSpace(*p)) return false;
            corners_.push_back(corner);
        }
        return corners_.size() >= 3;
    }

    // Where the survey's counts and this pass's disagree, an index would land in another
    // chunk's place: never silently.
    static void expectRoom(std::size_t next, std::size_t end) {
        if (next >= end) throw std::logic_error("OBJ reader: a chunk holds more than its survey");
    }

    void addPosition(int line) {
        const std::size_t i = next_.positions++;
        expectRoom(i, end_.positions);
        model_.positions[i] = {numbers_[0], numbers_[1], numbers_[2]};
        model_.positionLines[i] = line;
        // x y z [w], or x y z r g b with a colour per vertex.
        if (numbers_.size() >= 6)
            result_.colors.emplace_back(std::uint32_t(i), clampedColor(numbers_, 3));
    }
    void addNormal() {
        expectRoom(next_.normals, end_.normals);
        model_.normals[next_.normals++] = {numbers_[0], numbers_[1], numbers_[2]};
    }
    void addTexcoord() {
        expectRoom(next_.texcoords, end_.texcoords);
        model_.texcoords[next_.texcoords++] = {numbers_[0],
                                               numbers_.size() > 1 ? numbers_[1] : 0.0};
    }

    void addFace(int line) {
        const std::size_t n = corners_.size();
        expectRoom(next_.faces, end_.faces);
        expectRoom(next_.facePositions + n - 1, end_.facePositions);
        expectRoom(next_.triangles + n - 3, end_.triangles);
        const auto face = static_cast<std::uint32_t>(next_.faces++);
        if (!model_.triangles.facesAreTriangles()) { // else triangle `face` holds them
            for (const SourceCorner& corner : corners_)
                model_.facePositions[next_.facePositions++] = corner.position;
            model_.faceStarts[face + 1] = next_.facePositions;
        } else if (n != 3) {
            throw std::logic_error("OBJ reader: a polygon where the survey found triangles only");
        }
        if (n == 3) { // the common case, without a polygon's work
            model_.triangles.set(next_.triangles++,
                                 {{corners_[0], corners_[1], corners_[2]}, material_, face, line});
            return;
        }
        result_.polygons.push_back(
            {next_.triangles, face, material_, line, result_.polygonCorners.size(), n});
        result_.polygonCorners.insert(result_.polygonCorners.end(), corners_.begin(),
                                      corners_.end());
        next_.triangles += n - 2;
    }

    const std::string& fileName_;
    ObjChunkPlace next_; // where the next of each goes
    const ObjChunkPlace& end_;
    const ObjChunkMaterials& materials_;
    SourceModel& model_;
    ObjChunkResult& result_;
    std::uint32_t material_;
    std::size_t usemtlSeen_ = 0;
    Statement statement_; // storage reused from line to line
    Numbers numbers_;
    std::vector<SourceCorner> corners_; // a face's
};

} // namespace

ObjChunkResult fillObjChunk(std::string_view chunk, const std::string& fileName,
                            const ObjChunkPlace& place, const ObjChunkPlace& end,
                            const ObjChunkMaterials& materials, SourceModel& model,
                            PhaseProgress* progress) {
    ObjChunkResult result;
    ChunkReader reader(fileName, place, end, materials, model, result);
    LineWalker lines(chunk, place.firstLine);
    LogicalLine logical;
    ProgressShare share(progress, lines);
    try {
        while (lines.next(logical)) {
            share.update();
            reader.read(logical);
        }
    } catch (const SceneError& error) {
        result.error = error;
    }
    share.finish();
    return result;
}

FannedConcave splitObjPolygons(const ObjChunkResult& chunk, SourceModel& model) {
    FannedConcave fanned;
    std::vector<glm::dvec3> points;
    for (const ObjPolygon& polygon : chunk.polygons) {
        const SourceCorner* corners = chunk.polygonCorners.data() + polygon.firstCorner;
        points.clear();
        for (std::size_t i = 0; i < polygon.corners; ++i)
            points.push_back(model.positions[corners[i].position]);
        const PolygonTriangles split = triangulatePolygon(points);
        if (split.fannedConcave && fanned.count++ == 0) fanned.firstLine = polygon.line;
        std::size_t next = polygon.firstTriangle;
        for (const auto& [a, b, c] : split.triangles)
            model.triangles.set(next++, {{corners[a], corners[b], corners[c]},
                                         polygon.material,
                                         polygon.face,
                                         polygon.line});
    }
    return fanned;
}
