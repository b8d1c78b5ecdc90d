#include "model/source_triangles.h"

#include "base/populated_memory.h"
#include "base/release.h"

#include <numeric>
#include <stdexcept>
#include <string>

namespace {

bool hasNormal(const SourceTriangle& triangle) {
    for (const SourceCorner& corner : triangle.corners)
        if (corner.normal != kNoNormal) return true;
    return false;
}

bool hasTexcoord(const SourceTriangle& triangle) {
    for (const SourceCorner& corner : triangle.corners)
        if (corner.texcoord != kNoTexcoord) return true;
    return false;
}

glm::uvec3 normalsOf(const SourceTriangle& triangle) {
    return {triangle.corners[0].normal, triangle.corners[1].normal, triangle.corners[2].normal};
}

glm::uvec3 texcoordsOf(const SourceTriangle& triangle) {
    return {triangle.corners[0].texcoord, triangle.corners[1].texcoord,
            triangle.corners[2].texcoord};
}

} // namespace

void SourceTriangles::makeFacesTheTriangles() {
    if (!positions_.empty())
        throw std::logic_error("SourceTriangles::makeFacesTheTriangles: triangles are there");
    facesAreTriangles_ = true;
    release(faces_);
}

void SourceTriangles::keepFaceIndices() {
    if (!facesAreTriangles_) return;
    faces_.resize(positions_.size());
    std::iota(faces_.begin(), faces_.end(), std::uint32_t(0));
    facesAreTriangles_ = false;
}

void SourceTriangles::expectOwnFace(std::size_t t, std::uint32_t face) const {
    if (facesAreTriangles_ && face != t)
        throw std::logic_error("SourceTriangles: triangle " + std::to_string(t) + " is not face " +
                               std::to_string(face) + ", but each face is its triangle");
}

void SourceTriangles::resize(std::size_t n, bool normals, bool texcoords) {
    resizePopulated(positions_, n);
    resizePopulated(materials_, n);
    if (!facesAreTriangles_) resizePopulated(faces_, n);
    resizePopulated(lines_, n);
    withNormals_ = normals;
    withTexcoords_ = texcoords;
    if (withNormals_) resizePopulated(normals_, n);
    if (withTexcoords_) resizePopulated(texcoords_, n);
}

void SourceTriangles::set(std::size_t t, const SourceTriangle& triangle) {
    expectOwnFace(t, triangle.face);
    const SourceCorner* corners = triangle.corners;
    positions_[t] = {corners[0].position, corners[1].position, corners[2].position};
    materials_[t] = triangle.material;
    if (!facesAreTriangles_) faces_[t] = triangle.face;
    lines_[t] = triangle.line;
    if (withNormals_)
        normals_[t] = normalsOf(triangle);
    else if (hasNormal(triangle))
        throw std::logic_error("SourceTriangles::set: a normal, but none was made room for");
    if (withTexcoords_)
        texcoords_[t] = texcoordsOf(triangle);
    else if (hasTexcoord(triangle))
        throw std::logic_error("SourceTriangles::set: texture coordinates, but none were made "
                               "room for");
}

void SourceTriangles::push_back(const SourceTriangle& triangle) {
    const std::size_t before = positions_.size();
    expectOwnFace(before, triangle.face);
    if (!withNormals_ && hasNormal(triangle)) {
        normals_.assign(before, glm::uvec3(kNoNormal));
        withNormals_ = true;
    }
    if (!withTexcoords_ && hasTexcoord(triangle)) {
        texcoords_.assign(before, glm::uvec3(kNoTexcoord));
        withTexcoords_ = true;
    }
    const SourceCorner* corners = triangle.corners;
    positions_.push_back({corners[0].position, corners[1].position, corners[2].position});
    materials_.push_back(triangle.material);
    if (!facesAreTriangles_) faces_.push_back(triangle.face);
    lines_.push_back(triangle.line);
    if (withNormals_) normals_.push_back(normalsOf(triangle));
    if (withTexcoords_) texcoords_.push_back(texcoordsOf(triangle));
}

void SourceTriangles::reserve(std::size_t n) {
    positions_.reserve(n);
    materials_.reserve(n);
    if (!facesAreTriangles_) faces_.reserve(n);
    lines_.reserve(n);
}
