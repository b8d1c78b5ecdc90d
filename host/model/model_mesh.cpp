#include "model/model_mesh.h"

#include "base/parallel.h"
#include "base/populated_memory.h"
#include "model/exact_vectors.h"

#include <algorithm>
#include <cstring>

namespace {

using namespace exact_vectors;

bool isDegenerate(const std::vector<glm::dvec3>& positions, const glm::uvec3& corners) {
    const std::uint32_t a = corners[0], b = corners[1], c = corners[2];
    if (a == b || b == c || a == c) return true;
    return length(glm::cross(positions[b] - positions[a], positions[c] - positions[a])) == 0.0;
}

// A model's corner as a mesh vertex: its position, its texture coordinates' index and its
// normal, bit for bit, so that corners that agree on all three share a vertex (and its
// colour, which goes with the position).
struct CornerKey {
    std::uint32_t position = 0;
    std::uint32_t texcoord = kNoTexcoord;
    glm::dvec3 normal{0.0};
};

// The vertices made so far, looked up among those at the corner's position: a short chain
// in the order they were made. A model's triangles name nearby positions one after another,
// so the look-ups stay in the cache, where a hash table's missed it on every corner.
// A vertex is kept as the mesh will hold it, not as a key: its normal (not yet turned) in
// the mesh's array, its position's and texture coordinates' indices beside it, 8 bytes a
// vertex where a key took 32.
class VertexChains {
  public:
    VertexChains(std::size_t positions, bool texcoords, std::vector<glm::dvec3>& normals)
        : first_(positions, kNone), texcoords_(texcoords), normals_(normals) {
        // As many vertices as positions, the common case, without growing: a copy of
        // growing arrays costs more than their look-ups.
        // Their pages mapped on all threads: the look-ups that fill them run on one.
        reservePopulated(positionOf_, positions);
        reservePopulated(next_, positions);
        reservePopulated(normals_, positions);
        if (texcoords_) reservePopulated(texcoordOf_, positions);
    }

    // The vertex of key, made if no corner before had it. The chain holds only vertices at
    // key's position; texcoords and normal are compared bit for bit.
    std::uint32_t indexOf(const CornerKey& key) {
        std::uint32_t* link = &first_[key.position];
        for (std::uint32_t vertex = *link; vertex != kNone; vertex = next_[vertex]) {
            if ((!texcoords_ || texcoordOf_[vertex] == key.texcoord) &&
                std::memcmp(&normals_[vertex], &key.normal, sizeof key.normal) == 0)
                return vertex;
            link = &next_[vertex];
        }
        const auto vertex = static_cast<std::uint32_t>(positionOf_.size());
        *link = vertex; // before next_ grows, which may move what link points into
        positionOf_.push_back(key.position);
        if (texcoords_) texcoordOf_.push_back(key.texcoord);
        normals_.push_back(key.normal);
        next_.push_back(kNone);
        return vertex;
    }

    std::size_t size() const { return positionOf_.size(); }
    std::uint32_t positionOf(std::size_t vertex) const { return positionOf_[vertex]; }
    std::uint32_t texcoordOf(std::size_t vertex) const { return texcoordOf_[vertex]; }

  private:
    static constexpr std::uint32_t kNone = UINT32_MAX;
    std::vector<std::uint32_t> first_;                   // per position: its first vertex
    std::vector<std::uint32_t> next_;                    // per vertex: the next at its position
    std::vector<std::uint32_t> positionOf_, texcoordOf_; // per vertex (texcoords: if any)
    bool texcoords_;
    std::vector<glm::dvec3>& normals_; // per vertex
};

// Triangles are keyed this many at a time, on all threads, then looked up in order.
constexpr std::size_t kKeyBlock = std::size_t(1) << 15;

} // namespace

std::vector<TriangleFate> triangleFates(const SourceModel& model,
                                        const std::vector<glm::dvec3>& positions,
                                        const std::vector<bool>& farFaces) {
    std::vector<TriangleFate> fates(model.triangles.size());
    const std::vector<IndexRange> ranges = splitRange(fates.size(), 8192);
    parallelFor(ranges.size(), [&](std::size_t k) {
        for (std::size_t t = ranges[k].begin; t < ranges[k].end; ++t) {
            const SourceTriangles& source = model.triangles;
            fates[t] = !farFaces.empty() && farFaces[source.face(t)]  ? TriangleFate::far
                       : isDegenerate(positions, source.positions(t)) ? TriangleFate::degenerate
                                                                      : TriangleFate::kept;
        }
    });
    return fates;
}

bool needsSmoothNormals(const SourceModel& model, const std::vector<TriangleFate>& fates) {
    for (std::size_t t = 0; t < model.triangles.size(); ++t) {
        if (fates[t] != TriangleFate::kept) continue;
        if (!model.triangles.anyNormal()) return true;
        for (int c = 0; c < 3; ++c)
            if (model.triangles.corner(t, c).normal == kNoNormal) return true;
    }
    return false;
}

Mesh modelMesh(const SourceModel& model, const std::vector<glm::dvec3>& positions,
               const std::vector<glm::dvec3>& normals, const std::vector<TriangleFate>& fates,
               std::optional<SmoothNormals> smooth, const VertexPlacement& placement,
               PhaseProgress* progress) {
    const std::size_t triangles = model.triangles.size();
    // The kept triangles counted by ranges on all threads, for where each range's go.
    const std::vector<IndexRange> triangleRanges = splitRange(triangles, 1 << 16);
    const std::vector<std::size_t> keptBefore = countsBefore(triangleRanges, [&](IndexRange range) {
        return std::size_t(std::count(fates.begin() + std::ptrdiff_t(range.begin),
                                      fates.begin() + std::ptrdiff_t(range.end),
                                      TriangleFate::kept));
    });
    const std::size_t kept = keptBefore.back();
    Mesh mesh;
    reservePopulated(mesh.triangles, kept);
    const bool texcoords = !model.texcoords.empty();
    VertexChains vertexOf(positions.size(), texcoords, mesh.normals);
    // A block's corners keyed on all threads, then looked up in order on one, while the
    // others key the next block: the look-ups are the first part of each round, and the
    // thread that takes them joins the keying when done.
    std::vector<CornerKey> blockKeys[2];
    auto keyRange = [&](std::vector<CornerKey>& keys, std::size_t first, IndexRange range) {
        for (std::size_t i = range.begin; i < range.end; ++i) {
            if (fates[first + i] != TriangleFate::kept) continue;
            const std::uint32_t face = model.triangles.face(first + i);
            for (int c = 0; c < 3; ++c) {
                const SourceCorner corner = model.triangles.corner(first + i, c);
                CornerKey& key = keys[3 * i + c];
                key.position = corner.position;
                key.texcoord = corner.texcoord;
                key.normal = corner.normal != kNoNormal ? normals[corner.normal]
                                                        : smooth->at(face, corner.position);
            }
        }
    };
    auto lookUp = [&](const std::vector<CornerKey>& keys, std::size_t first) {
        const std::size_t count = std::min(kKeyBlock, triangles - first);
        for (std::size_t i = 0; i < count; ++i) {
            if (fates[first + i] != TriangleFate::kept) continue;
            glm::uvec3 triangle;
            for (int c = 0; c < 3; ++c) // in corner order: vertices are numbered as they come
                triangle[c] = vertexOf.indexOf(keys[3 * i + c]);
            mesh.triangles.push_back(triangle);
        }
        if (progress) progress->advance(count);
    };
    // Round r looks up block r - 1 and keys block r.
    for (std::size_t round = 0; round * kKeyBlock < triangles + kKeyBlock; ++round) {
        const std::size_t keyed = round * kKeyBlock;
        std::vector<IndexRange> ranges;
        if (keyed < triangles) {
            ranges = splitRange(std::min(kKeyBlock, triangles - keyed), 2048);
            blockKeys[round % 2].resize(3 * kKeyBlock);
        }
        const bool lookUps = round > 0;
        parallelFor(ranges.size() + 1, [&](std::size_t k) {
            if (k == 0) {
                if (lookUps) lookUp(blockKeys[(round + 1) % 2], keyed - kKeyBlock);
                return;
            }
            keyRange(blockKeys[round % 2], keyed, ranges[k - 1]);
        });
    }
    // The smooth normals go before the other arrays are made: the phase's peak of memory is
    // where the corners have their normals. The kept triangles' materials and lines are
    // copied after it, for the same reason.
    smooth.reset();
    // On all threads, each range's from the count of the ranges before it.
    resizePopulated(mesh.triangleMaterials, kept);
    resizePopulated(mesh.triangleLines, kept);
    parallelFor(triangleRanges.size(), [&](std::size_t k) {
        std::size_t slot = keptBefore[k];
        for (std::size_t t = triangleRanges[k].begin; t < triangleRanges[k].end; ++t) {
            if (fates[t] != TriangleFate::kept) continue;
            mesh.triangleMaterials[slot] = model.triangles.material(t);
            mesh.triangleLines[slot++] = model.triangles.line(t);
        }
    });

    // Each vertex's other attributes, from its position's and texture coordinates' indices;
    // its normal turned in place.
    const bool anyColor =
        !model.colors.empty() && std::any_of(model.colors.begin(), model.colors.end(),
                                             [](const auto& color) { return color.has_value(); });
    const std::size_t vertices = vertexOf.size();
    mesh.positions.resize(vertices);
    if (texcoords) mesh.texcoords.resize(vertices);
    if (anyColor) mesh.colors.resize(vertices);
    const std::vector<IndexRange> ranges = splitRange(vertices, 8192);
    parallelFor(ranges.size(), [&](std::size_t k) {
        for (std::size_t v = ranges[k].begin; v < ranges[k].end; ++v) {
            const std::uint32_t position = vertexOf.positionOf(v);
            mesh.positions[v] = placement.place(positions[position]);
            mesh.normals[v] = placement.turn(mesh.normals[v]);
            if (texcoords) {
                const std::uint32_t texcoord = vertexOf.texcoordOf(v);
                mesh.texcoords[v] =
                    texcoord == kNoTexcoord ? glm::dvec2(0.0) : model.texcoords[texcoord];
            }
            if (anyColor) {
                const auto& color = model.colors[position];
                mesh.colors[v] = color ? glm::dvec4(*color, 1.0) : glm::dvec4(0.0);
            }
        }
    });
    return mesh;
}
