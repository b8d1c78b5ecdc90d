// Walking the bounding volume hierarchy (host/packing/bvh.cpp builds it; node layout in shared.h),
// and the two scene queries shading uses, which walk it or test every primitive.
// Needs: Ray (camera.glsl), the primitive tests and brute-force loops (intersect.glsl),
// the node buffer and the specialization constants useHierarchy, sceneHasSpheres and
// sceneHasTriangles (trace.comp); fetchBvhNode and fetchSphere (scene_reads.glsl).

// The slab test's minimum and maximum: GLSL.std.450's NMin and NMax, which return the other
// operand when one is NaN, on every Vulkan device (GLSL's min and max leave NaN undefined).
// The slab test below lets the NaN of 0 * inf through to them, to be dropped.
// (GL_EXT_spirv_intrinsics, enabled in trace.comp.)
spirv_instruction(set = "GLSL.std.450", id = 79) float nanDroppingMin(float a, float b);
spirv_instruction(set = "GLSL.std.450", id = 80) float nanDroppingMax(float a, float b);
#ifdef RT_FP64
spirv_instruction(set = "GLSL.std.450", id = 79) double nanDroppingMin(double a, double b);
spirv_instruction(set = "GLSL.std.450", id = 80) double nanDroppingMax(double a, double b);
#endif

// A ray prepared for the slab test: 1/d per axis (+-inf where d is +-0, or so small that
// 1/d overflows), and per axis whether the box's maximum plane is the one the ray enters
// by (d < 0, -0 included), so that each slab's near and far planes are picked by a select
// instead of being sorted by a min and a max.
struct BoxRay {
    rvec3 origin;
    rvec3 invDirection;
    bvec3 entersAtMax;
};

BoxRay boxRay(Ray ray) {
    rvec3 inv = 1.0 / ray.direction;
    return BoxRay(ray.origin, inv, lessThan(inv, rvec3(0.0))); // -0 gives -inf: negative
}

// 1 + 2 gamma(3), gamma(n) = n eps / (1 - n eps), eps = 2^-24: the relative error bound
// of the slab distances (plane - o) * (1/d), three roundings each, applied to the exit
// distance (Ize 2013; Pharr, Jakob & Humphreys, pbrt-v3 section 3.9.2). In fp64, eps = 2^-53.
#ifdef RT_FP64
const double SLAB_EXIT_SCALE = 1.0000000000000007LF;
#else
const float SLAB_EXIT_SCALE = 1.0000003576;
#endif

// Robust ray/box slab test of Ize, "Robust BVH Ray Traversal", JCGT 2(2), 2013: the entry
// and exit distances are computed as (plane - origin) * (1/d) with correct rounding and the
// exit distance is scaled by 1 + 2 gamma(3), so that a box the exact ray touches is never
// missed, at its faces, edges and corners included (a closed box). Each slab's near plane
// (where the ray enters it) and far plane are chosen by the sign of 1/d (Williams et al.,
// "An Efficient and Robust Ray-Box Intersection Algorithm", JGT 2005): rounding is
// monotonic, so that gives the same distances as sorting the two by a min and a max.
// A zero direction component gives 1/d = +-inf: the slab's distances are then -inf or +inf
// (the origin inside the slab, or outside: a miss), and where the origin lies exactly in
// one of the slab's planes, 0 * inf = NaN. That plane limits nothing, since the ray runs in
// it and the box is closed, and NaN is what the NaN-dropping maximum and minimum below
// leave out: a near NaN does not raise the entry, a far NaN does not lower the exit. An
// origin in a face's plane with a nonzero direction component keeps its exact distance 0,
// so boxes the ray only touches at its origin stay culled beyond it.
// Why not GLSL's min and max on a sorted pair: lavapipe compiles a min or max whose
// operands may be NaN to three instructions (the operation, a NaN test and a select), and
// sorting and substituting for NaN cost about twice this test's instructions
// (docs/performance.md). A maximum or minimum against a constant is one instruction, and
// so is one against its result, which is known to be a number: hence the maximum begins
// with 0 and the minimum with FLOAT_MAX, not with tLimit (never above FLOAT_MAX, so the
// exit is the same).
// Returns whether the box is entered at some t in [0, tLimit] (scaled alike), and the
// entry t. In fp64 the float boxes (rounded outward by the host) are tested in double,
// exactly converted.
bool hitBox(BoxRay ray, rvec3 lo, rvec3 hi, real tLimit, out real tEntry) {
    rvec3 nearPlane = mix(lo, hi, ray.entersAtMax);
    rvec3 farPlane = mix(hi, lo, ray.entersAtMax);
    precise rvec3 tNear = (nearPlane - ray.origin) * ray.invDirection;
    precise rvec3 tFar = (farPlane - ray.origin) * ray.invDirection;
    tEntry = nanDroppingMax(nanDroppingMax(nanDroppingMax(real(0.0), tNear.x), tNear.y), tNear.z);
    real tExit = nanDroppingMin(
        nanDroppingMin(nanDroppingMin(nanDroppingMin(real(FLOAT_MAX), tFar.x), tFar.y), tFar.z),
        tLimit);
    return tEntry <= tExit * SLAB_EXIT_SCALE;
}

// The next real above a finite positive t (FLOAT_MAX gives +inf in fp32): a limit that
// lets a primitive at exactly t through, for the tie rule below.
#ifdef RT_FP64
double nextRealUp(double t) {
    uvec2 bits = unpackDouble2x32(t);
    uint carry;
    bits.x = uaddCarry(bits.x, 1u, carry);
    return packDouble2x32(uvec2(bits.x, bits.y + carry));
}
#else
float nextRealUp(float t) {
    return uintBitsToFloat(floatBitsToUint(t) + 1u);
}
#endif

// The primitives of one leaf against the ray, from its child reference (shared.h). Closest hit:
// equal distances go to the lower (kind, index), spheres first, which is what the brute-force loops
// give (they take primitives in that order and keep the first of equals), so both paths agree
// exactly. Returns true in any-hit mode when something was hit. The kind test folds away for a
// scene of one kind (specialization constants, trace.comp).
bool intersectLeaf(Ray ray, ShearedRay sheared, uint leaf, bool anyHitMode, inout Hit hit) {
    uint first = leaf & BVH_FIRST_MASK;
    uint end = first + ((leaf >> BVH_COUNT_SHIFT) & BVH_MAX_LEAF_COUNT);
    real limit = anyHitMode ? hit.t : nextRealUp(hit.t);
    real t;
    if (sceneHasSpheres && (!sceneHasTriangles || (leaf & BVH_LEAF_SPHERES) != 0u)) {
        uint i = first;
        if (i < end) { // do-while: see traverseBvh
            do {
                if (countWork) ++leafPrimitiveTests;
                if (!intersectSphere(ray, fetchSphere(i), limit, t)) continue;
                if (anyHitMode) return true;
                if (t < hit.t || hit.kind == HIT_TRIANGLE ||
                    (hit.kind == HIT_SPHERE && i < hit.index)) {
                    hit = Hit(t, HIT_SPHERE, i, rvec3(0.0));
                    limit = nextRealUp(t);
                }
            } while (++i < end);
        }
    } else {
        rvec3 barycentric;
        uint i = first;
        if (i < end) {
            do {
                if (countWork) ++leafPrimitiveTests;
                if (!intersectTriangle(ray, sheared, i, limit, t, barycentric)) continue;
                if (anyHitMode) return true;
                if (t < hit.t || (hit.kind == HIT_TRIANGLE && i < hit.index)) {
                    hit = Hit(t, HIT_TRIANGLE, i, barycentric);
                    limit = nextRealUp(t);
                }
            } while (++i < end);
        }
    }
    return false;
}

// A node's child references (shared.h).
uint leftChild(GpuBvhNode node) {
    return floatBitsToUint(node.leftMinAndRef.w);
}
uint rightChild(GpuBvhNode node) {
    return floatBitsToUint(node.rightMinAndRef.w);
}

// Iterative depth-first traversal with a stack of stackDepth entries, the scene's tree depth
// (trace.comp; the builder keeps it within BVH_STACK_SIZE). A step fetches one node, which
// holds both children's boxes (Aila & Laine's layout, shared.h), and tests both; the nearer
// hit child is visited next and the other's reference pushed. A popped child is visited
// whatever the closest hit so far: its own boxes and primitives are tested against that
// hit, so nothing beyond it is taken.
// Keeping each entry distance to skip such a child on the pop cost lavapipe more than the
// visits it saved: it was a third stack array (measured in docs/performance.md). A leaf is known
// from its reference, so its primitives are tested without fetching anything but them. Any-hit mode
// (shadow rays) returns at the first hit found. hit.t is the limit on entry (the light's distance
// for shadow rays, FLOAT_MAX for closest hit); returns whether any-hit mode found something.
//
// Loop shape "while-while" (Aila & Laine, HPG 2009): an inner loop walks interior nodes
// until the ray stands at a leaf, then the leaf is tested. lavapipe runs 8 rays as one
// SIMD vector and executes both sides of every branch, masked; with one loop holding both
// the interior and the leaf code ("if-if"), each step paid for a leaf test too. Same
// images, and faster on lavapipe (tools/kernel_costs --baseline compares two builds).
// For the same reason the next child is popped right where one is done with (a node with
// neither child hit, a leaf tested), not behind a flag at the top of the inner loop, which
// every step paid for.
// Loops test their condition at the end (do-while) here and in every loop of the kernel
// that runs a variable number of times: lavapipe leaves a loop only at the end of its body,
// when no lane is left, so with the test at the top (while, for) the whole body ran once
// more, masked, after the last lane had left: a node step per walk down, a primitive test
// per leaf, a light per shading point, a whole sample per pixel. Same images, 7% fewer
// instructions on table.scene (docs/performance.md).
bool traverseBvh(Ray ray, bool anyHitMode, inout Hit hit) {
    ShearedRay sheared = shearRay(ray);
    BoxRay slabRay = boxRay(ray);
    // Pending children's references, the top in stack[0]: a push moves every entry down one
    // place and a pop up one, with constant indices only, so the array lives in registers
    // (Mesa unrolls the loops over its constant length). Why not an array indexed by the
    // stack's size: lavapipe keeps such an array in memory and stores into it lane by lane,
    // each behind a branch on whether that lane is active, which mispredicted as rays
    // diverged (a quarter of the 100k knot's JIT samples, tools/kernel_profile); the
    // shifts cost a select per entry instead (docs/performance.md). One entry per level of the tree
    // is enough: the stack holds at most one entry per level above the current node.
    uint stack[stackDepth];
    // Loops of this exact shape (an int counter against a constant) are the ones Mesa counts
    // and unrolls; a uint one tested as i + 1u < stackDepth was not, and the kernel ran 2-3x
    // slower (a patch, measured in docs/performance.md).
#define STACK_LAST (int(stackDepth) - 1)
    uint stackSize = 0u;
    uint child = 0u; // the root: interior node 0
    for (;;) {
        if ((child & BVH_LEAF) == 0u) {
            do {
                if (countWork) ++nodeVisits;
                GpuBvhNode node = fetchBvhNode(child);
                real leftEntry, rightEntry;
                bool hitLeft = hitBox(slabRay, rvec3(node.leftMinAndRef.xyz),
                                      rvec3(node.leftMax.xyz), hit.t, leftEntry);
                bool hitRight = hitBox(slabRay, rvec3(node.rightMinAndRef.xyz),
                                       rvec3(node.rightMax.xyz), hit.t, rightEntry);
                // The child to visit next: the nearer of two hit, else the one hit.
                bool rightNext = hitRight && (!hitLeft || rightEntry < leftEntry);
                if (hitLeft && hitRight) {
                    for (int i = STACK_LAST; i > 0; --i)
                        stack[i] = stack[i - 1];
                    stack[0] = rightNext ? leftChild(node) : rightChild(node);
                    ++stackSize;
                }
                if (hitLeft || hitRight) {
                    child = rightNext ? rightChild(node) : leftChild(node);
                } else {
                    if (stackSize == 0u) return false;
                    --stackSize;
                    child = stack[0];
                    for (int i = 0; i < STACK_LAST; ++i)
                        stack[i] = stack[i + 1];
                }
            } while ((child & BVH_LEAF) == 0u);
        }
        if (intersectLeaf(ray, sheared, child, anyHitMode, hit)) return true;
        if (stackSize == 0u) return false;
        --stackSize;
        child = stack[0];
        for (int i = 0; i < STACK_LAST; ++i)
            stack[i] = stack[i + 1];
    }
}

// The nearest hit along the ray over every sphere and triangle.
Hit closestHit(Ray ray) {
    if (!useHierarchy) return closestHitEveryPrimitive(ray);
    Hit hit = Hit(FLOAT_MAX, HIT_NONE, 0u, rvec3(0.0));
    traverseBvh(ray, false, hit);
    return hit;
}

// Whether anything lies on the ray with 0 < t < tMax (shadow rays); stops at the first hit.
bool anyHit(Ray ray, real tMax) {
    if (!useHierarchy) return anyHitEveryPrimitive(ray, tMax);
    Hit hit = Hit(tMax, HIT_NONE, 0u, rvec3(0.0));
    return traverseBvh(ray, true, hit);
}
