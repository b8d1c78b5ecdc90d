// Flat patches (host/packing/flat_patches.h): which triangles the kernel's secondary rays skip
// together. Each case is a mesh whose patches are known by construction.
#include "packing/flat_patches.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace {

struct Mesh {
    std::vector<glm::dvec3> positions;
    std::vector<std::uint32_t> triangles;
    void add(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        triangles.insert(triangles.end(), {a, b, c});
    }
};

// Quad a b c d (in order around it) as triangles abc and acd.
void addQuad(Mesh& mesh, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
    const auto first = std::uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
    mesh.add(first, first + 1, first + 2);
    mesh.add(first, first + 2, first + 3);
}

std::size_t distinct(const std::vector<std::uint32_t>& patches) {
    return std::set<std::uint32_t>(patches.begin(), patches.end()).size();
}

} // namespace

TEST(FlatPatches, AQuadsHalvesAreOnePatch) {
    Mesh quad;
    addQuad(quad, {-1, -1, -3}, {1, -1, -3}, {1, 1, -4}, {-1, 1, -4});
    const auto patches = flatPatches(quad.positions, quad.triangles);
    ASSERT_EQ(patches.size(), 2u);
    EXPECT_EQ(patches[0], patches[1]);
}

TEST(FlatPatches, ABoxHasOnePatchPerFace) {
    // Eight shared corners, twelve triangles: the faces meet at right angles.
    Mesh box;
    for (int i = 0; i < 8; ++i)
        box.positions.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    const std::uint32_t faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                       {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& f : faces) {
        box.add(f[0], f[1], f[2]);
        box.add(f[0], f[2], f[3]);
    }
    const auto patches = flatPatches(box.positions, box.triangles);
    EXPECT_EQ(distinct(patches), 6u);
    for (std::size_t face = 0; face < 6; ++face)
        EXPECT_EQ(patches[2 * face], patches[2 * face + 1]) << "face " << face;
}

TEST(FlatPatches, AGroundOfManyTrianglesIsOnePatchAndAFoldSplitsIt) {
    // A 4 x 4 grid of quads 1e5 across at y = -1: one patch, whatever the scale of x and z.
    Mesh ground;
    const double step = 5e4;
    for (int j = 0; j <= 4; ++j)
        for (int i = 0; i <= 4; ++i)
            ground.positions.push_back({-1e5 + i * step, -1.0, -1e5 + j * step});
    for (std::uint32_t j = 0; j < 4; ++j)
        for (std::uint32_t i = 0; i < 4; ++i) {
            const std::uint32_t a = j * 5 + i;
            ground.add(a, a + 1, a + 6);
            ground.add(a, a + 6, a + 5);
        }
    EXPECT_EQ(distinct(flatPatches(ground.positions, ground.triangles)), 1u);
    // Lift the far row by 1 (a slope of 2e-5, far above the tolerance of 2^-20): the last
    // row of quads leaves the plane and the grid falls into two patches.
    for (int i = 0; i <= 4; ++i)
        ground.positions[4 * 5 + i].y += 1.0;
    const auto folded = flatPatches(ground.positions, ground.triangles);
    EXPECT_EQ(distinct(folded), 2u);
    EXPECT_NE(folded.front(), folded.back());
}

TEST(FlatPatches, CoplanarTrianglesThatDoNotTouchAreApart) {
    Mesh twoQuads;
    addQuad(twoQuads, {0, 0, -2}, {1, 0, -2}, {1, 1, -2}, {0, 1, -2});
    addQuad(twoQuads, {2, 0, -2}, {3, 0, -2}, {3, 1, -2}, {2, 1, -2});
    const auto patches = flatPatches(twoQuads.positions, twoQuads.triangles);
    EXPECT_EQ(patches[0], patches[1]);
    EXPECT_EQ(patches[2], patches[3]);
    EXPECT_NE(patches[0], patches[2]);
}

TEST(FlatPatches, ATiltedQuadRoundedToFloatStaysOnePatch) {
    // Written coplanar in decimals, then rounded to float as the GPU stores it: the fourth
    // corner is off the others' plane by float rounding only.
    auto rounded = [](glm::dvec3 p) { return glm::dvec3(glm::vec3(p)); };
    Mesh quad;
    addQuad(quad, rounded({0.1, 0.2, -3.3}), rounded({1.7, 0.5, -3.9}), rounded({1.9, 2.1, -4.7}),
            rounded({0.3, 1.8, -4.1}));
    const auto patches = flatPatches(quad.positions, quad.triangles);
    EXPECT_EQ(patches[0], patches[1]);
}

TEST(FlatPatches, ZeroAreaTrianglesAndConeApexesStayApart) {
    Mesh mesh;
    // A cone of 24 sides around its apex (vertex 0): every triangle in its own plane, more
    // planes than kPlanesPerVertex meet at the apex.
    mesh.positions.push_back({0, 1, -5});
    const int sides = 24;
    for (int k = 0; k < sides; ++k) {
        const double angle = 2.0 * M_PI * k / sides;
        mesh.positions.push_back({std::cos(angle), 0, -5 + std::sin(angle)});
    }
    for (std::uint32_t k = 0; k < std::uint32_t(sides); ++k)
        mesh.add(0, 1 + k, 1 + (k + 1) % sides);
    // A degenerate triangle on the cone's rim: all three corners on one line.
    mesh.positions.push_back({2, 0, -5});
    mesh.positions.push_back({3, 0, -5});
    mesh.add(1, std::uint32_t(sides + 1), std::uint32_t(sides + 2));
    const auto patches = flatPatches(mesh.positions, mesh.triangles);
    EXPECT_EQ(distinct(patches), std::size_t(sides + 1));
}
