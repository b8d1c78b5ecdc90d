// The hierarchy builder's boxes in registers (host/packing/bvh_boxes.h): the builder takes
// the same splits as with Box only if Box4 grows to the same corners, bit for bit, and
// measures the same half area, and a primitive's register corners are its box with the id
// masked out.
#include "packing/bvh_boxes.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using bvh_boxes::Box;
using bvh_boxes::Box4;
using bvh_boxes::Float4;

std::uint32_t bits(float value) {
    return std::bit_cast<std::uint32_t>(value);
}

// Coordinates that tell the min and max apart from their lookalikes: both zeros, ties,
// flat boxes, large and tiny magnitudes.
float awkwardCoordinate(std::mt19937& random) {
    static const float kValues[] = {0.0f, -0.0f, 1.0f, -1.0f, 1e30f, -1e30f, 1e-30f, 3.5f};
    std::uniform_int_distribution<int> pick(0, 9);
    const int k = pick(random);
    if (k < 8) return kValues[k];
    return std::uniform_real_distribution<float>(-10.0f, 10.0f)(random);
}

TEST(BvhBoxes, RegisterBoxesGrowAndMeasureAsBoxDoes) {
    std::mt19937 random(7);
    for (int trial = 0; trial < 2000; ++trial) {
        Box box;
        Box4 box4;
        EXPECT_EQ(bits(box4.halfArea()), bits(box.halfArea())) << "empty";
        for (int k = 0; k < trial % 5 + 1; ++k) {
            glm::vec3 a, b;
            for (int axis = 0; axis < 3; ++axis) {
                a[axis] = awkwardCoordinate(random);
                b[axis] = awkwardCoordinate(random);
            }
            const Box other{glm::min(a, b), glm::max(a, b)};
            box.grow(other);
            box4.grow(Float4{other.lo.x, other.lo.y, other.lo.z, 0.0f},
                      Float4{other.hi.x, other.hi.y, other.hi.z, 0.0f});
        }
        const Box fromRegisters = box4.box();
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_EQ(bits(fromRegisters.lo[axis]), bits(box.lo[axis])) << trial;
            EXPECT_EQ(bits(fromRegisters.hi[axis]), bits(box.hi[axis])) << trial;
        }
        EXPECT_EQ(bits(box4.halfArea()), bits(box.halfArea())) << trial;
    }
}

TEST(BvhBoxes, APrimitivesRegisterCornersAreItsBoxWithoutItsId) {
    // An id whose bits as a float are a NaN: the masked lane must still read 0.
    const PrimitiveBox ref{{-1.0f, 2.0f, -0.0f}, 0xffffffffu, {3.0f, 2.0f, 5.0f}, 0.0f};
    const Float4 lo = bvh_boxes::lowCorner(ref), hi = bvh_boxes::highCorner(ref);
    const float expectedLo[4] = {-1.0f, 2.0f, -0.0f, 0.0f};
    const float expectedHi[4] = {3.0f, 2.0f, 5.0f, 0.0f};
    for (int lane = 0; lane < 4; ++lane) {
        EXPECT_EQ(bits(lo[lane]), bits(expectedLo[lane])) << lane;
        EXPECT_EQ(bits(hi[lane]), bits(expectedHi[lane])) << lane;
    }
    const glm::vec3 centroid = bvh_boxes::centroidOf(ref);
    for (int axis = 0; axis < 3; ++axis)
        EXPECT_EQ(bits(bvh_boxes::centroidOf(ref, axis)), bits(centroid[axis]));
    EXPECT_EQ(centroid, glm::vec3(1.0f, 2.0f, 2.5f));
}

} // namespace
