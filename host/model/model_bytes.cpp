#include "model/model_bytes.h"

#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace {

// Arrays of trivially copyable values (positions, normals) go as their bytes, in one copy
// each, the triangles a whole SourceTriangle each: a model of millions of triangles
// crosses in tenths of a second.
class Writer {
  public:
    template <typename T> void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    template <typename T> void array(const std::vector<T>& values) {
        value<std::uint64_t>(values.size());
        if (!values.empty())
            bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    void text(const std::string& s) {
        value<std::uint64_t>(s.size());
        bytes_.append(s);
    }
    std::string take() { return std::move(bytes_); }

  private:
    std::string bytes_;
};

class Reader {
  public:
    explicit Reader(std::string_view bytes) : bytes_(bytes) {}
    template <typename T> T value() {
        static_assert(std::is_trivially_copyable_v<T>);
        T v;
        std::memcpy(&v, take(sizeof v), sizeof v);
        return v;
    }
    std::uint64_t count(std::size_t each) {
        const auto n = value<std::uint64_t>();
        if (each > 0 && n > (bytes_.size() - at_) / each) throw std::runtime_error("cut short");
        return n;
    }
    template <typename T> std::vector<T> array() {
        std::vector<T> values(count(sizeof(T)));
        const char* from = take(values.size() * sizeof(T));
        if (!values.empty()) std::memcpy(values.data(), from, values.size() * sizeof(T));
        return values;
    }
    std::string text() {
        const std::uint64_t n = count(1);
        return std::string(take(n), n);
    }
    bool done() const { return at_ == bytes_.size(); }

  private:
    const char* take(std::size_t n) {
        if (n > bytes_.size() - at_) throw std::runtime_error("cut short");
        const char* start = bytes_.data() + at_;
        at_ += n;
        return start;
    }
    std::string_view bytes_;
    std::size_t at_ = 0;
};

void check(bool holds) {
    if (!holds) throw std::runtime_error("an index out of range");
}

} // namespace

std::string modelBytes(const SourceModel& model) {
    Writer out;
    out.array(model.positions);
    out.array(model.positionLines);
    out.array(model.colors);
    out.array(model.normals);
    out.array(model.texcoords);
    out.array(model.facePositions);
    out.array(model.faceStarts);
    out.value<std::uint8_t>(model.triangles.facesAreTriangles());
    out.value<std::uint64_t>(model.triangles.size());
    for (std::size_t t = 0; t < model.triangles.size(); ++t)
        out.value(model.triangles[t]);
    out.value<std::uint64_t>(model.materials.size());
    for (const MeshMaterial& material : model.materials) {
        out.value(material.phong);
        out.text(material.diffuseTexture);
        out.value(material.textureFactor);
        out.value(material.emission);
    }
    out.value<std::uint64_t>(model.embeddedTextures.size());
    for (const auto& [textureName, bytes] : model.embeddedTextures) {
        out.text(textureName);
        out.text(bytes);
    }
    out.value<std::uint64_t>(model.warnings.size());
    for (const std::string& warning : model.warnings)
        out.text(warning);
    out.value<std::uint64_t>(model.notRendered.size());
    for (const auto& [what, count] : model.notRendered) {
        out.text(what);
        out.value<std::uint64_t>(count);
    }
    return out.take();
}

SourceModel modelFromBytes(std::string_view bytes) {
    Reader in(bytes);
    SourceModel model;
    model.positions = in.array<glm::dvec3>();
    model.positionLines = in.array<int>();
    model.colors = in.array<std::optional<glm::dvec3>>();
    model.normals = in.array<glm::dvec3>();
    model.texcoords = in.array<glm::dvec2>();
    model.facePositions = in.array<std::uint32_t>();
    model.faceStarts = in.array<std::size_t>();
    if (in.value<std::uint8_t>() != 0) model.triangles.makeFacesTheTriangles();
    const std::uint64_t triangles = in.count(sizeof(SourceTriangle));
    model.triangles.reserve(triangles);
    for (std::uint64_t t = 0; t < triangles; ++t) {
        const auto triangle = in.value<SourceTriangle>();
        check(!model.triangles.facesAreTriangles() || triangle.face == t);
        model.triangles.push_back(triangle);
    }
    model.materials.resize(in.count(sizeof(Material) + 8 + 2 * sizeof(glm::dvec3)));
    for (MeshMaterial& material : model.materials) {
        material.phong = in.value<Material>();
        material.diffuseTexture = in.text();
        material.textureFactor = in.value<glm::dvec3>();
        material.emission = in.value<glm::dvec3>();
    }
    const std::uint64_t embedded = in.count(16);
    for (std::uint64_t i = 0; i < embedded; ++i) {
        std::string textureName = in.text();
        model.embeddedTextures[textureName] = in.text();
    }
    model.warnings.resize(in.count(8));
    for (std::string& warning : model.warnings)
        warning = in.text();
    const std::uint64_t kinds = in.count(16);
    for (std::uint64_t i = 0; i < kinds; ++i) {
        std::string what = in.text();
        model.notRendered[what] = in.value<std::uint64_t>();
    }
    if (!in.done()) throw std::runtime_error("bytes left over");
    // Every index names what is there, as the readers guarantee.
    check(model.positionLines.size() == model.positions.size() &&
          (model.colors.empty() || model.colors.size() == model.positions.size()));
    check(!model.faceStarts.empty() && model.faceStarts.front() == 0 &&
          model.faceStarts.back() == model.facePositions.size());
    check(!model.triangles.facesAreTriangles() || model.faceStarts.size() == 1);
    for (std::size_t i = 1; i < model.faceStarts.size(); ++i)
        check(model.faceStarts[i - 1] <= model.faceStarts[i]);
    for (const std::uint32_t p : model.facePositions)
        check(p < model.positions.size());
    for (std::size_t k = 0; k < model.triangles.size(); ++k) {
        const SourceTriangle t = model.triangles[k];
        for (const SourceCorner& corner : t.corners)
            check(corner.position < model.positions.size() &&
                  (corner.normal == kNoNormal || corner.normal < model.normals.size()) &&
                  (corner.texcoord == kNoTexcoord || corner.texcoord < model.texcoords.size()));
        check(t.material < model.materials.size() && t.face < faceCount(model));
    }
    return model;
}
