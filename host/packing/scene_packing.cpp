#include "packing/scene_packing.h"

#include "base/deduplicator.h"
#include "base/ordered_dedup.h"
#include "base/parallel.h"
#include "base/phase_progress.h"
#include "base/populated_memory.h"
#include "base/release.h"
#include "base/startup_phases.h"
#include "packing/flat_patches.h"
#include "scene/scene_triangles.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

// The C++ mirror must have exactly the std430 layout the shader reads.
static_assert(sizeof(gpu::GpuMaterial) == 32);
static_assert(sizeof(gpu::GpuLight) == 32);
static_assert(sizeof(gpu::GpuMaterialTexture) == 16);
static_assert(sizeof(gpu::GpuBvhNode) == 64, "one node per 64-byte cache line");
static_assert(offsetof(gpu::GpuBvhNode, leftMax) == 16);
static_assert(offsetof(gpu::GpuBvhNode, rightMinAndRef) == 32);
static_assert(offsetof(gpu::GpuBvhNode, rightMax) == 48);
static_assert(sizeof(gpu::GpuFrameParams) == 128);
static_assert(sizeof(gpu::GpuFrameParams) <= 128, "push constants are limited to 128 bytes");
static_assert(offsetof(gpu::GpuFrameParams, image) == 80);
static_assert(offsetof(gpu::GpuFrameParams, dispatch) == 112);

namespace {

glm::vec4 toVec4(const glm::dvec3& v, double w = 0.0) {
    return glm::vec4(glm::vec3(v), static_cast<float>(w));
}

gpu::GpuMaterial toGpuMaterial(const Material& material) {
    return {toVec4(material.diffuse, material.shininess),
            toVec4(material.specular, material.mirror)};
}

// A material as the GPU stores it, the unit of material deduplication: its Phong terms and
// its texture (zero when it has none).
struct PackedMaterial {
    gpu::GpuMaterial phong;
    gpu::GpuMaterialTexture texture;
};

// A vertex as the GPU stores it, the unit of vertex deduplication.
struct PackedVertex {
    glm::vec4 position; // w zero
    glm::vec4 normal;   // w zero
    std::uint32_t material;
    std::uint32_t padding;    // zero, so equal vertices have equal bytes
    glm::vec2 texcoord;       // zero when the scene has no textures
    glm::dvec4 exactPosition; // fp64: the position in double, w zero; fp32: zero
};

// The vertices every corner may make, before deduplication: each candidate's fields apart,
// so that a scene holds only what it uses: 28 bytes a candidate for the position, normal
// and material, texture coordinates only with textures, the double position only in fp64
// (a whole PackedVertex took 80 bytes, a scan's largest array while it is packed). A
// PackedVertex is made of them wherever one is compared.
class Candidates {
  public:
    // bound: at least the candidates to come, whose pages are mapped on all threads.
    Candidates(std::size_t bound, bool textured, bool fp64) : textured_(textured), fp64_(fp64) {
        reservePopulated(cores_, bound);
        if (textured_) reservePopulated(texcoords_, bound);
        if (fp64_) reservePopulated(exactPositions_, bound);
    }

    std::uint32_t add(const PackedVertex& vertex) {
        cores_.push_back({glm::vec3(vertex.position), glm::vec3(vertex.normal), vertex.material});
        if (textured_) texcoords_.push_back(vertex.texcoord);
        if (fp64_) exactPositions_.push_back(glm::dvec3(vertex.exactPosition));
        return std::uint32_t(cores_.size() - 1);
    }

    std::size_t size() const { return cores_.size(); }

    // count candidates more, each then set once (set) on any thread; the first's index.
    std::size_t grow(std::size_t count) {
        const std::size_t first = cores_.size();
        cores_.resize(first + count);
        if (textured_) texcoords_.resize(first + count);
        if (fp64_) exactPositions_.resize(first + count);
        return first;
    }
    void set(std::size_t c, const PackedVertex& vertex) {
        cores_[c] = {glm::vec3(vertex.position), glm::vec3(vertex.normal), vertex.material};
        if (textured_) texcoords_[c] = vertex.texcoord;
        if (fp64_) exactPositions_[c] = glm::dvec3(vertex.exactPosition);
    }

    PackedVertex operator[](std::size_t c) const {
        PackedVertex vertex{};
        vertex.position = glm::vec4(cores_[c].position, 0.0f);
        vertex.normal = glm::vec4(cores_[c].normal, 0.0f);
        vertex.material = cores_[c].material;
        if (textured_) vertex.texcoord = texcoords_[c];
        if (fp64_) vertex.exactPosition = glm::dvec4(exactPositions_[c], 0.0);
        return vertex;
    }

    // Keeps candidate firstOf[k] as the k-th, in place: firstOf increases and
    // firstOf[k] >= k, so none is overwritten before it is read.
    void keep(const std::vector<std::uint32_t>& firstOf) {
        for (std::size_t k = 0; k < firstOf.size(); ++k) {
            if (firstOf[k] == k) continue;
            cores_[k] = cores_[firstOf[k]];
            if (textured_) texcoords_[k] = texcoords_[firstOf[k]];
            if (fp64_) exactPositions_[k] = exactPositions_[firstOf[k]];
        }
        cores_.resize(firstOf.size());
        if (textured_) texcoords_.resize(firstOf.size());
        if (fp64_) exactPositions_.resize(firstOf.size());
    }

  private:
    struct Core {
        glm::vec3 position;
        glm::vec3 normal;
        std::uint32_t material;
    };
    static_assert(sizeof(Core) == 28);
    bool textured_, fp64_;
    std::vector<Core> cores_;
    std::vector<glm::vec2> texcoords_;
    std::vector<glm::dvec3> exactPositions_;
};

// Whether the mesh's triangles all have one material, its vertices no colours, and its
// vertices are numbered in the order its corners first use them (as a model's are,
// model/model_mesh.h): then each vertex packs as one candidate, in vertex order.
bool hasOneMaterialInFirstUseOrder(const Mesh& mesh) {
    if (!mesh.colors.empty() || mesh.triangles.empty()) return false;
    const std::uint32_t material = mesh.triangleMaterials.front();
    if (std::any_of(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(),
                    [&](std::uint32_t m) { return m != material; }))
        return false;
    std::uint32_t used = 0; // the vertices used so far: 0 to used - 1
    for (const glm::uvec3& triangle : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            if (triangle[k] > used) return false;
            used += triangle[k] == used;
        }
    return used == mesh.positions.size();
}

// Each texture's place in the texel array (GpuMaterialTexture), by Scene::textures' index;
// the texels themselves go into pixels.
std::vector<gpu::GpuMaterialTexture> packTextures(const std::vector<Texture>& textures,
                                                  std::vector<std::uint32_t>& pixels) {
    std::vector<gpu::GpuMaterialTexture> placements;
    std::size_t total = 0;
    for (const Texture& texture : textures)
        total += std::size_t(texture.image.width) * std::size_t(texture.image.height);
    if (total > UINT32_MAX)
        throw std::runtime_error("the scene's textures hold " + std::to_string(total) +
                                 " texels, more than a 32-bit index reaches");
    pixels.reserve(total);
    for (const Texture& texture : textures) {
        placements.push_back(
            {glm::uvec4(pixels.size(), texture.image.width, texture.image.height, 0u)});
        const std::vector<std::uint8_t>& rgba = texture.image.rgba;
        for (std::size_t i = 0; i + 4 <= rgba.size(); i += 4) // R in the low byte: unpackUnorm4x8
            pixels.push_back(std::uint32_t(rgba[i]) | std::uint32_t(rgba[i + 1]) << 8 |
                             std::uint32_t(rgba[i + 2]) << 16 | std::uint32_t(rgba[i + 3]) << 24);
    }
    return placements;
}

} // namespace

struct PackingInput {
    PackingInput(std::size_t candidateBound, bool withTextures, bool inFp64)
        : textured(withTextures), fp64(inFp64), candidates(candidateBound, withTextures, inFp64) {}
    bool textured, fp64;
    PackedScene packed; // all but the triangles and vertices
    std::vector<PackedMaterial> materials;
    Candidates candidates;
    std::vector<std::uint32_t> cornersOfTriangles; // each triangle's three candidates
};

void PackingInputDeleter::operator()(PackingInput* input) const {
    delete input;
}

PackingInputPtr readForPacking(const Scene& scene, Precision precision) {
    const bool fp64 = precision == Precision::Fp64;
    const bool textured = !scene.textures.empty();
    // The scene file's triangles, then each mesh's (scene_triangles.h's numbering). Every
    // corner that may make a vertex is a candidate, in order; finishPacking then
    // deduplicates them on all threads (orderedDedup: the indices of Deduplicator called on
    // them in turn), as vertices (whole) and as corners (their positions alone, whatever
    // their normals and materials: what the flat patches join triangles through).
    std::size_t candidateBound = 3 * scene.triangles.size();
    for (const Mesh& mesh : scene.meshes)
        candidateBound += mesh.positions.size();
    PackingInputPtr input(new PackingInput(candidateBound, textured, fp64));
    PackedScene& packed = input->packed;
    Candidates& candidates = input->candidates;
    std::vector<std::uint32_t>& cornersOfTriangles = input->cornersOfTriangles;
    packed.ambient = toVec4(scene.ambient);
    packed.lights = packLights(scene.lights);
    const std::vector<gpu::GpuMaterialTexture> texturePlacements =
        packTextures(scene.textures, packed.texturePixels);
    Deduplicator<PackedMaterial> materials(input->materials, 64);
    // Neighbouring vertices often share a material: compare with the last one first.
    PackedMaterial lastMaterial{};
    std::uint32_t lastMaterialIndex = UINT32_MAX;
    auto materialIndex = [&](const Material& material, std::int64_t texture) {
        PackedMaterial packedMaterial{toGpuMaterial(material), {}};
        if (texture >= 0) packedMaterial.texture = texturePlacements[std::size_t(texture)];
        if (lastMaterialIndex == UINT32_MAX ||
            std::memcmp(&packedMaterial, &lastMaterial, sizeof lastMaterial) != 0) {
            lastMaterial = packedMaterial;
            lastMaterialIndex = materials.indexOf(packedMaterial);
        }
        return lastMaterialIndex;
    };

    packed.spheres.reserve(scene.spheres.size());
    packed.sphereMaterials.reserve(scene.spheres.size());
    for (const Sphere& sphere : scene.spheres) {
        packed.spheres.push_back(toVec4(sphere.center, sphere.radius));
        packed.sphereMaterials.push_back(materialIndex(sphere.material, -1));
        if (fp64) packed.spheres64.push_back(glm::dvec4(sphere.center, sphere.radius));
    }

    const std::size_t triangles = triangleCount(scene);
    reservePopulated(cornersOfTriangles, 3 * triangles);
    auto packedVertex = [&](const glm::dvec3& position, const glm::dvec3& normal,
                            std::uint32_t material, glm::dvec2 texcoord) {
        PackedVertex vertex{};
        vertex.position = toVec4(position);
        vertex.normal = toVec4(normal);
        vertex.material = material;
        if (textured) vertex.texcoord = glm::vec2(texcoord);
        if (fp64) vertex.exactPosition = glm::dvec4(position, 0.0);
        return vertex;
    };
    auto candidate = [&](const Vertex& vertex, std::int64_t texture, glm::dvec2 texcoord) {
        return candidates.add(packedVertex(vertex.position, vertex.normal,
                                           materialIndex(vertex.material, texture), texcoord));
    };
    for (const Triangle& triangle : scene.triangles)
        for (int k = 0; k < 3; ++k)
            cornersOfTriangles.push_back(candidate(triangle.vertices[k], -1, glm::dvec2(0.0)));
    // A mesh's corner packs the same as any earlier corner of its vertex whose triangle has
    // the same material: that one's candidate stands for it, rather than one a corner.
    struct PackedCorner {
        std::uint32_t material = UINT32_MAX; // the mesh's: none yet
        std::uint32_t candidate = 0;
    };
    std::vector<PackedCorner> packedCorners;
    PhaseProgress progress("Packing the scene", triangles);
    progress.advance(scene.triangles.size());
    for (const Mesh& mesh : scene.meshes) {
        // A model's mesh of one material, its vertices numbered as its corners first use
        // them: vertex v's candidate is the v-th, made on all threads.
        if (hasOneMaterialInFirstUseOrder(mesh)) {
            const auto texture = triangleTexture(mesh, 0);
            const std::uint32_t material =
                materialIndex(cornerMaterial(mesh, 0, 0), texture ? std::int64_t(*texture) : -1);
            const std::size_t first = candidates.grow(mesh.positions.size());
            parallelForRanges(mesh.positions.size(), 1 << 14, [&](IndexRange range) {
                for (std::size_t v = range.begin; v < range.end; ++v)
                    candidates.set(first + v,
                                   packedVertex(mesh.positions[v], mesh.normals[v], material,
                                                vertexTexcoord(mesh, std::uint32_t(v))));
            });
            const std::size_t corners = cornersOfTriangles.size();
            cornersOfTriangles.resize(corners + 3 * mesh.triangles.size());
            parallelForRanges(mesh.triangles.size(), 1 << 14, [&](IndexRange range) {
                for (std::size_t t = range.begin; t < range.end; ++t)
                    for (int k = 0; k < 3; ++k)
                        cornersOfTriangles[corners + 3 * t + std::size_t(k)] =
                            std::uint32_t(first + mesh.triangles[t][k]);
            });
            progress.advance(mesh.triangles.size());
            continue;
        }
        packedCorners.assign(mesh.positions.size(), PackedCorner{});
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            if (t % 65536 == 65535) progress.advance(65536);
            const auto texture = triangleTexture(mesh, t);
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = mesh.triangles[t][k];
                PackedCorner& done = packedCorners[v];
                if (done.material != mesh.triangleMaterials[t]) {
                    done.candidate = candidate(
                        Vertex{mesh.positions[v], mesh.normals[v], cornerMaterial(mesh, t, v)},
                        texture ? std::int64_t(*texture) : -1, vertexTexcoord(mesh, v));
                    done.material = mesh.triangleMaterials[t];
                }
                cornersOfTriangles.push_back(done.candidate);
            }
        }
    }
    return input;
}

PackedScene finishPacking(PackingInputPtr input) {
    const bool fp64 = input->fp64, textured = input->textured;
    PackedScene packed = std::move(input->packed);
    Candidates& candidates = input->candidates;
    // The vertices first: each triangle's from its candidates, which then go.
    {
        const std::vector<std::uint32_t>& corners = input->cornersOfTriangles;
        const OrderedDedup vertexIndices = orderedDedup<PackedVertex>(
            candidates.size(), [&](std::size_t c) { return candidates[c]; });
        resizePopulated(packed.triangles, corners.size() / 3);
        const std::vector<IndexRange> blocks = splitRange(packed.triangles.size(), 1 << 16);
        parallelFor(blocks.size(), [&](std::size_t b) {
            for (std::size_t t = blocks[b].begin; t < blocks[b].end; ++t)
                packed.triangles[t] = glm::uvec4(vertexIndices.indexOf[corners[3 * t]],
                                                 vertexIndices.indexOf[corners[3 * t + 1]],
                                                 vertexIndices.indexOf[corners[3 * t + 2]], 0u);
        });
        release(input->cornersOfTriangles);
        candidates.keep(vertexIndices.firstOf);
    }
    // The flat patches, through the vertices' positions (the float ones in fp32, which the
    // GPU computes with): equal positions are one corner. The vertices' first appearances
    // are their candidates' in order, so the corners are numbered as among the candidates.
    {
        auto cornerOf = [&](std::size_t v) {
            const PackedVertex vertex = candidates[v];
            return fp64 ? glm::dvec4(glm::dvec3(vertex.exactPosition), 0.0)
                        : glm::dvec4(glm::dvec3(glm::vec3(vertex.position)), 0.0);
        };
        const OrderedDedup cornerIndices = orderedDedup<glm::dvec4>(candidates.size(), cornerOf);
        std::vector<glm::dvec3> cornerPositions;
        resizePopulated(cornerPositions, cornerIndices.firstOf.size());
        parallelForRanges(cornerPositions.size(), 1 << 15, [&](IndexRange range) {
            for (std::size_t k = range.begin; k < range.end; ++k)
                cornerPositions[k] = glm::dvec3(cornerOf(cornerIndices.firstOf[k]));
        });
        const std::vector<std::uint32_t> patches =
            flatPatches(cornerPositions, packed.triangles, cornerIndices.indexOf);
        parallelForRanges(packed.triangles.size(), 1 << 16, [&](IndexRange range) {
            for (std::size_t t = range.begin; t < range.end; ++t)
                packed.triangles[t].w = patches[t];
        });
    }
    // 28 bytes a vertex: the material index rides in the position's unused w, and the
    // normal takes three floats rather than a padded vec4. Written on all threads.
    const std::size_t vertices = candidates.size();
    resizePopulated(packed.vertexPositions, vertices);
    resizePopulated(packed.vertexNormals, 3 * vertices);
    if (fp64) resizePopulated(packed.vertexPositions64, vertices);
    if (textured) resizePopulated(packed.vertexTexcoords, vertices);
    parallelForRanges(vertices, 1 << 15, [&](IndexRange range) {
        for (std::size_t v = range.begin; v < range.end; ++v) {
            const PackedVertex vertex = candidates[v];
            packed.vertexPositions[v] =
                glm::vec4(glm::vec3(vertex.position), std::bit_cast<float>(vertex.material));
            for (int axis = 0; axis < 3; ++axis)
                packed.vertexNormals[3 * v + std::size_t(axis)] = vertex.normal[axis];
            if (fp64)
                packed.vertexPositions64[v] =
                    glm::dvec4(glm::dvec3(vertex.exactPosition), double(vertex.material));
            if (textured) packed.vertexTexcoords[v] = vertex.texcoord;
        }
    });
    for (const PackedMaterial& material : input->materials) {
        packed.materials.push_back(material.phong);
        if (textured) packed.materialTextures.push_back(material.texture);
    }
    return packed;
}

PackedScene packSceneInFileOrder(const Scene& scene, Precision precision) {
    return finishPacking(readForPacking(scene, precision));
}

std::vector<gpu::GpuLight> packLights(const std::vector<Light>& lights) {
    std::vector<gpu::GpuLight> packed;
    for (const Light& light : lights)
        packed.push_back({toVec4(light.position), toVec4(light.color)});
    return packed;
}

// Primitive boxes. A triangle's box is the exact min and max of its float corners, so its
// edges lie in the box's closed faces and the robust slab test (shaders/bvh.glsl) admits
// every ray that the watertight triangle test admits through an edge or a vertex. A
// sphere's box is centre -+ radius rounded to float, which can cut into the sphere by
// half an ulp, and the sphere test itself rounds; it is enlarged by 2^-20 of its largest
// coordinate magnitude (about 8 ulps) so that a ray the sphere test reports as grazing it
// also enters its box, and the hierarchy finds exactly the hits that testing every
// primitive finds.
namespace {

constexpr double kSphereBoxMargin = 1.0 / 1048576.0;

PrimitiveBox primitiveBox(glm::vec3 lo, glm::vec3 hi) {
    return {{lo.x, lo.y, lo.z}, 0, {hi.x, hi.y, hi.z}, 0.0f};
}

// The nearest float at or below (direction -1) or above (+1) each coordinate: a float box
// that holds the double one.
glm::vec3 roundOutward(glm::dvec3 v, float direction) {
    glm::vec3 rounded(v);
    for (int axis = 0; axis < 3; ++axis)
        if ((double(rounded[axis]) - v[axis]) * direction < 0.0)
            rounded[axis] = std::nextafter(rounded[axis], direction * INFINITY);
    return rounded;
}

PrimitiveBox primitiveBox(glm::dvec3 lo, glm::dvec3 hi) {
    return primitiveBox(roundOutward(lo, -1.0f), roundOutward(hi, 1.0f));
}

} // namespace

GpuTriangleArrayBytes gpuTriangleArrayBytes(const PackedScene& packed) {
    const bool fp64 = !packed.vertexPositions64.empty();
    GpuTriangleArrayBytes bytes;
    bytes.corners = 3 * packed.triangles.size() * (fp64 ? sizeof(glm::dvec4) : sizeof(glm::vec4));
    bytes.lastVertices = packed.triangles.size() * sizeof(std::uint32_t);
    bytes.normalsAndMaterials = packed.vertexPositions.size() * sizeof(glm::vec4);
    return bytes;
}

void writeTriangleCorners(const PackedScene& packed, void* destination) {
    const bool fp64 = !packed.vertexPositions64.empty();
    auto* corners = static_cast<glm::vec4*>(destination);
    auto* corners64 = static_cast<glm::dvec4*>(destination);
    parallelForRanges(packed.triangles.size(), 1 << 15, [&](IndexRange range) {
        for (std::size_t t = range.begin; t < range.end; ++t) {
            const glm::uvec4& triangle = packed.triangles[t];
            const std::uint32_t words[3] = {triangle.w, triangle.x, triangle.y};
            for (std::size_t k = 0; k < 3; ++k) {
                if (fp64)
                    corners64[3 * t + k] = glm::dvec4(
                        glm::dvec3(packed.vertexPositions64[triangle[int(k)]]), double(words[k]));
                else
                    corners[3 * t + k] =
                        glm::vec4(glm::vec3(packed.vertexPositions[triangle[int(k)]]),
                                  std::bit_cast<float>(words[k]));
            }
        }
    });
}

void writeLastVertices(const PackedScene& packed, void* destination) {
    auto* last = static_cast<std::uint32_t*>(destination);
    parallelForRanges(packed.triangles.size(), 1 << 16, [&](IndexRange range) {
        for (std::size_t t = range.begin; t < range.end; ++t)
            last[t] = packed.triangles[t].z;
    });
}

void writeNormalsAndMaterials(const PackedScene& packed, void* destination) {
    auto* out = static_cast<glm::vec4*>(destination);
    parallelForRanges(packed.vertexPositions.size(), 1 << 15, [&](IndexRange range) {
        for (std::size_t v = range.begin; v < range.end; ++v)
            out[v] = glm::vec4(packed.vertexNormals[3 * v], packed.vertexNormals[3 * v + 1],
                               packed.vertexNormals[3 * v + 2], packed.vertexPositions[v].w);
    });
}

GpuTriangleArrays gpuTriangleArrays(const PackedScene& packed) {
    const bool fp64 = !packed.vertexPositions64.empty();
    GpuTriangleArrays arrays;
    if (fp64) {
        arrays.corners64.resize(3 * packed.triangles.size());
        writeTriangleCorners(packed, arrays.corners64.data());
    } else {
        arrays.corners.resize(3 * packed.triangles.size());
        writeTriangleCorners(packed, arrays.corners.data());
    }
    arrays.lastVertices.resize(packed.triangles.size());
    writeLastVertices(packed, arrays.lastVertices.data());
    arrays.normalsAndMaterials.resize(packed.vertexPositions.size());
    writeNormalsAndMaterials(packed, arrays.normalsAndMaterials.data());
    return arrays;
}

std::uint32_t vertexMaterial(const PackedScene& packed, std::size_t v) {
    return std::bit_cast<std::uint32_t>(packed.vertexPositions.at(v).w);
}

namespace {

// The boxes of the given spheres and triangle corners, float (fp32) or double (fp64): the
// same margins in both, computed in double; a float box is rounded to nearest (the margin
// covers it), a double one outward to float (primitiveBox).
template <typename Vec4>
PrimitiveBounds boundsOf(const std::vector<Vec4>& spheres, const std::vector<Vec4>& positions,
                         const std::vector<glm::uvec4>& triangles) {
    using Vec3 = glm::vec<3, typename Vec4::value_type>;
    PrimitiveBounds bounds;
    bounds.sphereCount = std::uint32_t(spheres.size());
    for (const Vec4& sphere : spheres) {
        glm::dvec3 center(sphere);
        double magnitude =
            std::max({std::abs(center.x), std::abs(center.y), std::abs(center.z)}) + sphere.w;
        double reach = double(sphere.w) + kSphereBoxMargin * magnitude;
        bounds.boxes.push_back(primitiveBox(Vec3(center - reach), Vec3(center + reach)));
    }
    // The triangles' boxes on all threads, each written at its place.
    const std::size_t first = bounds.boxes.size();
    resizePopulated(bounds.boxes, first + triangles.size());
    const std::vector<IndexRange> blocks = splitRange(triangles.size(), 1 << 16);
    parallelFor(blocks.size(), [&](std::size_t k) {
        for (std::size_t t = blocks[k].begin; t < blocks[k].end; ++t) {
            const glm::uvec4 triangle = triangles[t];
            Vec3 a(positions[triangle.x]);
            Vec3 b(positions[triangle.y]);
            Vec3 c(positions[triangle.z]);
            bounds.boxes[first + t] =
                primitiveBox(glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)));
        }
    });
    return bounds;
}

} // namespace

PrimitiveBounds primitiveBounds(const PackedScene& packed) {
    if (!packed.spheres64.empty() || !packed.vertexPositions64.empty())
        return boundsOf(packed.spheres64, packed.vertexPositions64, packed.triangles);
    return boundsOf(packed.spheres, packed.vertexPositions, packed.triangles);
}

void applyLeafOrder(PackedScene& packed, const Bvh& bvh) {
    if (bvh.sphereOrder.size() != packed.spheres.size() ||
        bvh.triangleOrder.size() != packed.triangles.size())
        throw std::logic_error("applyLeafOrder: the hierarchy was built for another scene");
    std::vector<glm::vec4> spheres(packed.spheres.size());
    std::vector<std::uint32_t> sphereMaterials(packed.spheres.size());
    std::vector<glm::dvec4> spheres64(packed.spheres64.size());
    for (std::size_t slot = 0; slot < spheres.size(); ++slot) {
        spheres[slot] = packed.spheres[bvh.sphereOrder[slot]];
        sphereMaterials[slot] = packed.sphereMaterials[bvh.sphereOrder[slot]];
        if (!spheres64.empty()) spheres64[slot] = packed.spheres64[bvh.sphereOrder[slot]];
    }
    std::vector<glm::uvec4> triangles;
    resizePopulated(triangles, packed.triangles.size());
    const std::vector<IndexRange> blocks = splitRange(triangles.size(), 1 << 16);
    parallelFor(blocks.size(), [&](std::size_t k) {
        for (std::size_t slot = blocks[k].begin; slot < blocks[k].end; ++slot)
            triangles[slot] = packed.triangles[bvh.triangleOrder[slot]];
    });
    packed.spheres = std::move(spheres);
    packed.spheres64 = std::move(spheres64);
    packed.sphereMaterials = std::move(sphereMaterials);
    packed.triangles = std::move(triangles);
}

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point from) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - from)
        .count();
}

} // namespace

PackedScene packScene(const Scene& scene, Acceleration acceleration, Precision precision) {
    const auto start = std::chrono::steady_clock::now();
    PackedScene packed = packSceneInFileOrder(scene, precision);
    recordPhase("pack", millisecondsSince(start));
    arrangeForHierarchy(packed, acceleration);
    return packed;
}

void arrangeForHierarchy(PackedScene& packed, Acceleration acceleration) {
    auto start = std::chrono::steady_clock::now();
    Bvh bvh = buildBvh(primitiveBounds(packed));
    HierarchyReport& report = packed.hierarchy;
    report.buildMs = millisecondsSince(start);
    recordPhase("hierarchy", report.buildMs);
    start = std::chrono::steady_clock::now();
    applyLeafOrder(packed, bvh);
    packed.sphereOrder = std::move(bvh.sphereOrder);
    packed.triangleOrder = std::move(bvh.triangleOrder);
    report.primitives = packed.spheres.size() + packed.triangles.size();
    report.nodes = bvh.nodes.size();
    report.depth = bvh.depth;
    report.used = useHierarchy(acceleration, report.primitives);
    if (report.used) packed.bvhNodes = std::move(bvh.nodes);
    recordPhase("pack", millisecondsSince(start)); // the leaf order applied
}

std::string accelerationSummary(const HierarchyReport& report) {
    char line[160];
    if (report.used)
        std::snprintf(line, sizeof line,
                      "Acceleration: BVH, %zu two-wide nodes, depth %u, built in %.1f ms",
                      report.nodes, report.depth, report.buildMs);
    else
        std::snprintf(line, sizeof line,
                      "Acceleration: none, every primitive tested (%zu primitives)",
                      report.primitives);
    return line;
}
