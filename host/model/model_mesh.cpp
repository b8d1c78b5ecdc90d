#include "model/model_mesh.h"

#include "base/parallel.h"
#include "model/exact_vectors.h"
#include "model/smooth_normals.h"

#include <algorithm>
#include <cstring>
#include <optional>

namespace {

using namespace exact_vectors;

bool isDegenerate(const std::vector<glm::dvec3>& positions, const SourceTriangle& triangle) {
    const std::uint32_t a = triangle.corners[0].position, b = triangle.corners[1].position,
                        c = triangle.corners[2].position;
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
static_assert(sizeof(CornerKey) == 32); // no padding: compared as bytes

// The vertices made so far, looked up among those at the corner's position: a short chain
// in the order they were made. A model's triangles name nearby positions one after another,
// so the look-ups stay in the cache, where a hash table's missed it on every corner.
class VertexChains {
  public:
    explicit VertexChains(std::size_t positions) : first_(positions, kNone) {}

    // The vertex of key, made (appended to keys) if no corner before had it.
    std::uint32_t indexOf(const CornerKey& key, std::vector<CornerKey>& keys) {
        std::uint32_t* link = &first_[key.position];
        for (std::uint32_t vertex = *link; vertex != kNone; vertex = next_[vertex]) {
            if (std::memcmp(&keys[vertex], &key, sizeof key) == 0) return vertex;
            link = &next_[vertex];
        }
        const auto vertex = static_cast<std::uint32_t>(keys.size());
        *link = vertex; // before next_ grows, which may move what link points into
        keys.push_back(key);
        next_.push_back(kNone);
        return vertex;
    }

  private:
    static constexpr std::uint32_t kNone = UINT32_MAX;
    std::vector<std::uint32_t> first_; // per position: its first vertex
    std::vector<std::uint32_t> next_;  // per vertex: the next at its position
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
            const SourceTriangle& triangle = model.triangles[t];
            fates[t] = !farFaces.empty() && farFaces[triangle.face] ? TriangleFate::far
                       : isDegenerate(positions, triangle)          ? TriangleFate::degenerate
                                                                    : TriangleFate::kept;
        }
    });
    return fates;
}

Mesh modelMesh(const SourceModel& model, const std::vector<glm::dvec3>& positions,
               const std::vector<glm::dvec3>& normals, const std::vector<TriangleFate>& fates,
               double creaseDegrees, const std::vector<bool>& farFaces,
               const VertexPlacement& placement, PhaseProgress* progress) {
    const std::size_t triangles = model.triangles.size();
    std::size_t kept = 0;
    bool anyUnnormaled = false; // a kept corner without a normal: the smooth ones are made
    for (std::size_t t = 0; t < triangles; ++t) {
        if (fates[t] != TriangleFate::kept) continue;
        ++kept;
        for (const SourceCorner& corner : model.triangles[t].corners)
            anyUnnormaled = anyUnnormaled || corner.normal == kNoNormal;
    }
    std::optional<SmoothNormals> smooth;
    if (anyUnnormaled) smooth.emplace(model, positions, creaseDegrees, farFaces);

    Mesh mesh;
    mesh.triangles.reserve(kept);
    mesh.triangleMaterials.reserve(kept);
    mesh.triangleLines.reserve(kept);
    std::vector<CornerKey> keys; // one per vertex
    keys.reserve(positions.size());
    VertexChains vertexOf(positions.size());
    std::vector<CornerKey> blockKeys(3 * kKeyBlock);
    for (std::size_t first = 0; first < triangles; first += kKeyBlock) {
        const std::size_t count = std::min(kKeyBlock, triangles - first);
        const std::vector<IndexRange> ranges = splitRange(count, 2048);
        parallelFor(ranges.size(), [&](std::size_t k) {
            for (std::size_t i = ranges[k].begin; i < ranges[k].end; ++i) {
                if (fates[first + i] != TriangleFate::kept) continue;
                const SourceTriangle& source = model.triangles[first + i];
                for (int c = 0; c < 3; ++c) {
                    const SourceCorner& corner = source.corners[c];
                    CornerKey& key = blockKeys[3 * i + c];
                    key.position = corner.position;
                    key.texcoord = corner.texcoord;
                    key.normal = corner.normal != kNoNormal
                                     ? normals[corner.normal]
                                     : smooth->at(source.face, corner.position);
                }
            }
        });
        for (std::size_t i = 0; i < count; ++i) {
            if (fates[first + i] != TriangleFate::kept) continue;
            const SourceTriangle& source = model.triangles[first + i];
            glm::uvec3 triangle;
            for (int c = 0; c < 3; ++c) // in corner order: vertices are numbered as they come
                triangle[c] = vertexOf.indexOf(blockKeys[3 * i + c], keys);
            mesh.triangles.push_back(triangle);
            mesh.triangleMaterials.push_back(source.material);
            mesh.triangleLines.push_back(source.line);
        }
        if (progress) progress->advance(count);
    }

    // Each vertex's attributes, from its key.
    const bool anyColor = std::any_of(model.colors.begin(), model.colors.end(),
                                      [](const auto& color) { return color.has_value(); });
    mesh.positions.resize(keys.size());
    mesh.normals.resize(keys.size());
    if (!model.texcoords.empty()) mesh.texcoords.resize(keys.size());
    if (anyColor) mesh.colors.resize(keys.size());
    const std::vector<IndexRange> ranges = splitRange(keys.size(), 8192);
    parallelFor(ranges.size(), [&](std::size_t k) {
        for (std::size_t v = ranges[k].begin; v < ranges[k].end; ++v) {
            const CornerKey& key = keys[v];
            mesh.positions[v] = placement.place(positions[key.position]);
            mesh.normals[v] = placement.turn(key.normal);
            if (!model.texcoords.empty())
                mesh.texcoords[v] =
                    key.texcoord == kNoTexcoord ? glm::dvec2(0.0) : model.texcoords[key.texcoord];
            if (anyColor) {
                const auto& color = model.colors[key.position];
                mesh.colors[v] = color ? glm::dvec4(*color, 1.0) : glm::dvec4(0.0);
            }
        }
    });
    return mesh;
}
