#include "model/source_model.h"

namespace {

// The faces so far are the triangles: each listed, and each triangle given its face's index.
void listFaces(SourceModel& model) {
    const std::size_t n = model.triangles.size();
    model.facePositions.resize(3 * n);
    model.faceStarts.resize(n + 1);
    for (std::size_t t = 0; t < n; ++t) {
        for (int c = 0; c < 3; ++c)
            model.facePositions[3 * t + c] = model.triangles.positions(t)[c];
        model.faceStarts[t + 1] = 3 * (t + 1);
    }
    model.triangles.keepFaceIndices();
}

} // namespace

std::uint32_t addFace(SourceModel& model, std::span<const std::uint32_t> positions) {
    SourceTriangles& triangles = model.triangles;
    if (triangles.empty() && model.faceStarts.size() == 1 && !triangles.facesAreTriangles())
        triangles.makeFacesTheTriangles();
    if (triangles.facesAreTriangles()) {
        if (positions.size() == 3) return static_cast<std::uint32_t>(triangles.size());
        listFaces(model);
    }
    model.facePositions.insert(model.facePositions.end(), positions.begin(), positions.end());
    model.faceStarts.push_back(model.facePositions.size());
    return static_cast<std::uint32_t>(faceCount(model) - 1);
}
