// A model's triangles as its reader states them (source_model.h): each a triangle of a
// face's fan, its corners' indices into the model's positions, normals and texture
// coordinates, its material, face and line.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

// A corner's texcoord, and its normal, when its face gives none.
inline constexpr std::uint32_t kNoTexcoord = UINT32_MAX;
inline constexpr std::uint32_t kNoNormal = UINT32_MAX;

// One corner of a face: indices into SourceModel's positions, normals and texcoords (0-based).
struct SourceCorner {
    std::uint32_t position = 0;
    std::uint32_t normal = kNoNormal; // kNoNormal: the corner gets a smooth normal
    std::uint32_t texcoord = kNoTexcoord;
};

// A triangle of a face's fan (a polygon is split from its first corner), whole: what the
// readers make and SourceTriangles hands out, not how a model keeps it.
struct SourceTriangle {
    SourceCorner corners[3];
    std::uint32_t material = 0; // into SourceModel::materials
    std::uint32_t face = 0;     // the face (faceCount, facePositions) it was split from
    int line = 0;               // the face's line in its file (0: none), as readers count
};

// A model's triangles, an array a field, the normals' and texture coordinates' only when
// some corner has one, the faces' only when a face is not a triangle: a scan's (positions and
// triangles alone) take 20 bytes a triangle, where SourceTriangles in one array took 56.
class SourceTriangles {
  public:
    std::size_t size() const { return positions_.size(); }
    bool empty() const { return positions_.empty(); }

    SourceTriangle operator[](std::size_t t) const {
        SourceTriangle triangle;
        for (int c = 0; c < 3; ++c)
            triangle.corners[c] = corner(t, c);
        triangle.material = materials_[t];
        triangle.face = face(t);
        triangle.line = lines_[t];
        return triangle;
    }
    SourceCorner corner(std::size_t t, int c) const {
        return {positions_[t][c], withNormals_ ? normals_[t][c] : kNoNormal,
                withTexcoords_ ? texcoords_[t][c] : kNoTexcoord};
    }
    const glm::uvec3& positions(std::size_t t) const { return positions_[t]; }
    std::uint32_t material(std::size_t t) const { return materials_[t]; }
    std::uint32_t face(std::size_t t) const {
        return facesAreTriangles_ ? static_cast<std::uint32_t>(t) : faces_[t];
    }
    int line(std::size_t t) const { return lines_[t]; }
    // Whether the triangles hold normals (texture coordinates): else no corner has one.
    bool anyNormal() const { return withNormals_; }
    bool anyTexcoord() const { return withTexcoords_; }
    // Whether triangle t is face t, each face a triangle of its own (no face array kept).
    bool facesAreTriangles() const { return facesAreTriangles_; }

    // From the first triangle on, triangle t is face t: what most large models are (every
    // face of three corners), 4 bytes a triangle not kept here and 20 not in SourceModel's
    // faces. Only before any triangle; set and push_back then take only such triangles.
    void makeFacesTheTriangles();
    // From now on each triangle keeps its face's index, the faces so far being their
    // triangles (face(t) stays t for those).
    void keepFaceIndices();

    // n triangles to be set, their pages mapped on all threads; with normals (texcoords)
    // when some may have one.
    void resize(std::size_t n, bool normals, bool texcoords);
    // Triangle t of those resize made.
    void set(std::size_t t, const SourceTriangle& triangle);
    // One more triangle; the normals (texcoords) array is made with the first corner that
    // has one.
    void push_back(const SourceTriangle& triangle);
    void reserve(std::size_t n);

  private:
    // A logic error if each face is its triangle and face is not t.
    void expectOwnFace(std::size_t t, std::uint32_t face) const;

    bool withNormals_ = false, withTexcoords_ = false, facesAreTriangles_ = false;
    std::vector<glm::uvec3> positions_;
    std::vector<glm::uvec3> normals_, texcoords_;  // kNoNormal, kNoTexcoord: a corner without
    std::vector<std::uint32_t> materials_, faces_; // faces_: empty if facesAreTriangles_
    std::vector<int> lines_;
};
