// Ray/primitive intersection, and the loops that test every primitive (closest hit, any
// hit): the path for scenes too small for a hierarchy to pay (see bvh.glsl).
// Both primitive kinds are two-sided; a hit needs tMin < t < tMax with tMin = 0.
// Needs: Ray (camera.glsl), the scene reads (scene_reads.glsl), params and the
// specialization constants stableSphereTest and watertightTriangles (trace.comp).

const float FLOAT_MAX = 3.402823466e+38;

const uint HIT_NONE = 0u;
const uint HIT_SPHERE = 1u;
const uint HIT_TRIANGLE = 2u;

struct Hit {
    real t;            // distance along the ray (its direction is unit length)
    uint kind;         // HIT_NONE, HIT_SPHERE or HIT_TRIANGLE
    uint index;        // which sphere or triangle
    rvec3 barycentric; // triangles: weights of vertices 0, 1, 2
};

// Ray/sphere test in the numerically stable form of Haines et al., "Precision Improvements
// for Ray/Sphere Intersection", Ray Tracing Gems ch. 7 (2019): the discriminant comes from
// r^2 - |f - (f.d/a) d|^2 (no b^2 - ac cancellation) and the roots from q, c/q and q/a (no
// -b + sqrt(...) cancellation). Returns the nearer root in (0, tMax); from inside that is
// the far side.
bool intersectSphereStable(Ray ray, rvec4 centerRadius, real tMax, out real t) {
    rvec3 f = ray.origin - centerRadius.xyz;
    real a = dot(ray.direction, ray.direction);
    real b = -dot(f, ray.direction); // a t^2 - 2 b t + c = 0
    real r2 = centerRadius.w * centerRadius.w;
    rvec3 l = f + (b / a) * ray.direction; // f without its component along the ray
    real discriminant = a * (r2 - dot(l, l));
    if (discriminant < 0.0) return false;
    real c = dot(f, f) - r2;
    real q = b + (b >= 0.0 ? sqrt(discriminant) : -sqrt(discriminant));
    real t0 = c / q; // NaN only for a ray grazing the sphere from a point on it
    real t1 = q / a;
    real tNear = t0 < t1 ? t0 : t1; // comparisons, not min/max, so a NaN cannot win
    real tFar = t0 < t1 ? t1 : t0;
    t = tNear > 0.0 ? tNear : tFar;
    return t > 0.0 && t < tMax;
}

// The textbook ray/sphere test (--sphere-test naive): roots (-b -+ sqrt(b^2 - a c)) / a of
// a t^2 + 2 b t + c = 0 with b = f.d. Loses digits where the stable form does not: b^2 and
// a c cancel in the discriminant for a small or distant sphere, and -b + sqrt(...) cancels.
bool intersectSphereTextbook(Ray ray, rvec4 centerRadius, real tMax, out real t) {
    rvec3 f = ray.origin - centerRadius.xyz;
    real a = dot(ray.direction, ray.direction);
    real b = dot(f, ray.direction);
    real c = dot(f, f) - centerRadius.w * centerRadius.w;
    real discriminant = b * b - a * c;
    if (discriminant < 0.0) return false;
    real root = sqrt(discriminant);
    real tNear = (-b - root) / a;
    real tFar = (-b + root) / a;
    t = tNear > 0.0 ? tNear : tFar;
    return t > 0.0 && t < tMax;
}

// The sphere test chosen by --sphere-test (a specialization constant: the other is compiled out).
bool intersectSphere(Ray ray, rvec4 centerRadius, real tMax, out real t) {
    if (stableSphereTest) return intersectSphereStable(ray, centerRadius, tMax, t);
    return intersectSphereTextbook(ray, centerRadius, tMax, t);
}

// A ray prepared for the watertight triangle test: axes permuted so the dominant direction
// component is z (kx, ky, kz), and the shear that maps the direction onto +z.
struct ShearedRay {
    rvec3 origin;
    uvec3 axes;  // kx, ky, kz
    rvec3 shear; // Sx, Sy, Sz
};

// Per-ray setup of the watertight test (Woop, Benthin & Wald 2013, section 3).
ShearedRay shearRay(Ray ray) {
    rvec3 d = abs(ray.direction);
    uint kz = d.x > d.y ? (d.x > d.z ? 0u : 2u) : (d.y > d.z ? 1u : 2u);
    uint kx = kz == 2u ? 0u : kz + 1u;
    uint ky = kx == 2u ? 0u : kx + 1u;
    if (ray.direction[kz] < 0.0) { // keep the winding: swap kx and ky
        uint swap = kx;
        kx = ky;
        ky = swap;
    }
    real dz = ray.direction[kz];
    return ShearedRay(ray.origin, uvec3(kx, ky, kz),
                      rvec3(ray.direction[kx] / dz, ray.direction[ky] / dz, 1.0 / dz));
}

// Watertight ray/triangle test of Woop, Benthin & Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013; two-sided (no backface culling). `precise` keeps the
// edge functions bit-identical for the two triangles of a shared edge, so a ray through
// the edge hits one of them. The paper's double-precision recomputation for an edge value
// of exactly 0 is left out: a 0 counts as inside for both neighbours, which still leaves
// no crack. Degenerate triangles (det == 0 or a zero cross product) are never hit.
// Returns t in (0, tMax) and the barycentric weights of vertices a, b, c.
bool intersectTriangleWatertight(ShearedRay ray, rvec3 a, rvec3 b, rvec3 c, real tMax, out real t,
                                 out rvec3 barycentric) {
    uint kx = ray.axes.x, ky = ray.axes.y, kz = ray.axes.z;
    precise rvec3 A = a - ray.origin;
    precise rvec3 B = b - ray.origin;
    precise rvec3 C = c - ray.origin;
    precise real ax = A[kx] - ray.shear.x * A[kz];
    precise real ay = A[ky] - ray.shear.y * A[kz];
    precise real bx = B[kx] - ray.shear.x * B[kz];
    precise real by = B[ky] - ray.shear.y * B[kz];
    precise real cx = C[kx] - ray.shear.x * C[kz];
    precise real cy = C[ky] - ray.shear.y * C[kz];
    precise real u = cx * by - cy * bx; // edge functions; u weighs vertex a
    precise real v = ax * cy - ay * cx;
    precise real w = bx * ay - by * ax;
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
    real det = u + v + w;
    if (det == 0.0) return false;
    t = ray.shear.z * (u * A[kz] + v * B[kz] + w * C[kz]) / det;
    if (!(t > 0.0 && t < tMax)) return false;
    // A zero-area triangle can still get det != 0 from the rounding of its sheared corners,
    // but a line has no area to hit. Checked last, so only for rays that would hit.
    if (all(equal(cross(b - a, c - a), rvec3(0.0)))) return false;
    barycentric = rvec3(u, v, w) / det;
    return true;
}

// Moller & Trumbore, "Fast, Minimum Storage Ray-Triangle Intersection", JGT 2(1), 1997,
// two-sided (--triangle-test mt). Each triangle computes its barycentrics from its own
// edge vectors with its own roundings, so a ray through an edge shared by two triangles
// can miss both (a crack). Only an exactly zero determinant counts as parallel (the
// paper's epsilon of 1e-6 would reject every triangle of a scene scaled small), so what
// it differs in from the watertight test is watertightness itself. A zero-area triangle
// is never hit, as the model of docs/model.md asks.
bool intersectTriangleMollerTrumbore(Ray ray, rvec3 a, rvec3 b, rvec3 c, real tMax, out real t,
                                     out rvec3 barycentric) {
    rvec3 edge1 = b - a, edge2 = c - a;
    rvec3 p = cross(ray.direction, edge2);
    real det = dot(edge1, p);
    if (det == 0.0) return false;
    real inverseDet = 1.0 / det;
    rvec3 toOrigin = ray.origin - a;
    real u = dot(toOrigin, p) * inverseDet;
    if (u < 0.0 || u > 1.0) return false;
    rvec3 q = cross(toOrigin, edge1);
    real v = dot(ray.direction, q) * inverseDet;
    if (v < 0.0 || u + v > 1.0) return false;
    t = dot(edge2, q) * inverseDet;
    if (!(t > 0.0 && t < tMax)) return false;
    if (all(equal(cross(edge1, edge2), rvec3(0.0)))) return false;
    barycentric = rvec3(1.0 - u - v, u, v);
    return true;
}

// Triangle i against the ray with the test chosen by --triangle-test (a specialization
// constant: the other is compiled out, and so is the shear setup when unused). The flat
// patch a ray leaves is never hit by it (--offset error-bound, ray_offset.glsl).
bool intersectTriangle(Ray ray, ShearedRay sheared, uint i, real tMax, out real t,
                       out rvec3 barycentric) {
    rvec3 a, b, c;
    uint flatPatch = fetchTriangleCorners(i, a, b, c);
    if (rayOffsetKind == RAY_OFFSET_ERROR_BOUND && flatPatch == ray.leaving) return false;
    if (watertightTriangles)
        return intersectTriangleWatertight(sheared, a, b, c, tMax, t, barycentric);
    return intersectTriangleMollerTrumbore(ray, a, b, c, tMax, t, barycentric);
}

// The nearest hit along the ray over every sphere and triangle (brute-force loop). Of equal
// distances the first tested is kept: spheres first, then by index.
Hit closestHitEveryPrimitive(Ray ray) {
    Hit hit = Hit(FLOAT_MAX, HIT_NONE, 0u, rvec3(0.0));
    real t;
    for (uint i = 0u; sceneHasSpheres && i < sphereCount; ++i) {
        if (intersectSphere(ray, sphereToTest(i), hit.t, t))
            hit = Hit(t, HIT_SPHERE, i, rvec3(0.0));
    }
    ShearedRay sheared = shearRay(ray);
    rvec3 barycentric;
    uint i = 0u;
    if (sceneHasTriangles && triangleCount > 0u) { // do-while: see traverseBvh (bvh.glsl)
        do {
            if (intersectTriangle(ray, sheared, i, hit.t, t, barycentric)) {
                hit = Hit(t, HIT_TRIANGLE, i, barycentric);
            }
        } while (++i < triangleCount);
    }
    return hit;
}

// Whether anything lies on the ray with 0 < t < tMax, testing every primitive.
bool anyHitEveryPrimitive(Ray ray, real tMax) {
    real t;
    for (uint i = 0u; sceneHasSpheres && i < sphereCount; ++i) {
        if (intersectSphere(ray, fetchSphere(i), tMax, t)) return true;
    }
    ShearedRay sheared = shearRay(ray);
    rvec3 barycentric;
    uint i = 0u;
    if (sceneHasTriangles && triangleCount > 0u) {
        do {
            if (intersectTriangle(ray, sheared, i, tMax, t, barycentric)) return true;
        } while (++i < triangleCount);
    }
    return false;
}
