// A small scene's spheres baked into the kernel, on the brute-force path (no hierarchy):
// the sphere count is a specialization constant (and the light count too), and main copies
// the spheres into a private array before any branch. Why: lavapipe loads a buffer element
// once for the whole SIMD vector only outside all control flow; inside a loop every read
// is a gather per lane. With the count known, the driver unrolls the closest-hit loop over
// the array (a loop whose trip count is the length of an array it indexes always is), each
// index becomes a constant, the array becomes registers, and the loop loads nothing.
// Only that loop reads the copy, measured (docs/performance.md): unrolled, the any-hit
// loop of the shadow rays can no longer stop once all 8 lanes have hit, and baked
// triangles (nine floats each, and the watertight test's per-lane axis choice) made the
// kernel slower from four triangles on. Reads at an index known only at run time (the
// hit's, in shading) keep the texel or storage path.
// Needs: the spheres' storage binding and the specialization constants bakedSpheres and
// bakedSphereCount (trace.comp); fetchSphere (scene_reads.glsl).

// An array's length must be at least 1; a count of 0 leaves its loop empty.
const uint BAKED_SPHERE_SLOTS = bakedSphereCount + uint(bakedSphereCount == 0u);
rvec4 bakedSphereCopies[BAKED_SPHERE_SLOTS];

// Copies the spheres into the array above; main calls it first, outside all control flow.
void loadBakedSpheres() {
    if (!bakedSpheres) return;
    for (uint i = 0u; i < bakedSphereCount; ++i)
        bakedSphereCopies[i] = spheres[i];
}

// Sphere i for the closest-hit loop over every sphere: the baked copy when there is one.
rvec4 sphereToTest(uint i) {
    if (bakedSpheres) return bakedSphereCopies[i];
    return fetchSphere(i);
}
