// The boxes of the hierarchy builder (bvh.cpp): a box as ranges keep it, the same box in
// two registers for the per-primitive work of binning, and a primitive's box with its id
// as the builder moves it. The register forms compute the same floats as Box does.
#pragma once

#include "packing/bvh.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

namespace bvh_boxes {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Box {
    glm::vec3 lo{kInfinity};
    glm::vec3 hi{-kInfinity};
    void grow(const Box& other) {
        lo = glm::min(lo, other.lo);
        hi = glm::max(hi, other.hi);
    }
    void grow(const glm::vec3& point) {
        lo = glm::min(lo, point);
        hi = glm::max(hi, point);
    }
    // Half the surface area; 0 for an empty box.
    float halfArea() const {
        glm::vec3 e = glm::max(hi - lo, glm::vec3(0.0f));
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

// Four floats in one register (the GCC and Clang vector extension: SSE on x86-64, NEON on
// ARM): a box corner as binning grows it, x y z and a fourth lane that is always 0.
using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));

// Lane by lane as glm::min and glm::max choose (the second operand when it is smaller or
// larger), so that a box grows to the same bits as Box::grow.
inline Float4 min4(Float4 a, Float4 b) {
    return b < a ? b : a;
}
inline Float4 max4(Float4 a, Float4 b) {
    return b > a ? b : a;
}

// A box in two registers, for the per-primitive work of binning: a third of the
// instructions of Box's component by component min and max.
struct Box4 {
    Float4 lo{kInfinity, kInfinity, kInfinity, 0.0f};
    Float4 hi{-kInfinity, -kInfinity, -kInfinity, 0.0f};
    void grow(const Box4& other) { grow(other.lo, other.hi); }
    void grow(Float4 otherLo, Float4 otherHi) {
        lo = min4(lo, otherLo);
        hi = max4(hi, otherHi);
    }
    Box box() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
    // Box::halfArea's float, from the same operations.
    float halfArea() const {
        const Float4 e = max4(hi - lo, Float4{});
        return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
    }
};

// A primitive as the builder moves it (bvh.h's PrimitiveBox): its box and its id, half a
// cache line, partitioned in place so that a range's primitives are read in order when
// binned and partitioned. Arrays rather than glm vectors, whose operator[] is a switch on
// the axis.
static_assert(sizeof(PrimitiveBox) == 32 && offsetof(PrimitiveBox, id) == 12 &&
              offsetof(PrimitiveBox, zero) == 28);

inline Box boxOf(const PrimitiveBox& primitive) {
    return {{primitive.lo[0], primitive.lo[1], primitive.lo[2]},
            {primitive.hi[0], primitive.hi[1], primitive.hi[2]}};
}
// The same float as 0.5f * (lo + hi) of the input box, whatever the order of the ids.
inline glm::vec3 centroidOf(const PrimitiveBox& primitive) {
    const Box box = boxOf(primitive);
    return 0.5f * (box.lo + box.hi);
}
inline float centroidOf(const PrimitiveBox& primitive, int axis) {
    return 0.5f * (primitive.lo[axis] + primitive.hi[axis]);
}
// The box's corners in registers, fourth lanes 0 (the id's bits masked out of lo's; zero
// is 0).
inline Float4 lowCorner(const PrimitiveBox& primitive) {
    Float4 corner;
    std::memcpy(&corner, &primitive, sizeof corner);
    return Float4(Int4(corner) & Int4{-1, -1, -1, 0});
}
inline Float4 highCorner(const PrimitiveBox& primitive) {
    Float4 corner;
    std::memcpy(&corner, primitive.hi, sizeof corner);
    return corner;
}

// A bin of the SAH sweep: the boxes of its primitives and of their centroids, and their count.
struct Bin {
    Box4 bounds, centroids;
    std::uint32_t count = 0;
};

} // namespace bvh_boxes
