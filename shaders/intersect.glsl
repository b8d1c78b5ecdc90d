// Ray/primitive intersection, and the loops that test every primitive (closest hit, any
// hit): the path for scenes too small for a hierarchy to pay (see bvh.glsl).
// Both primitive kinds are two-sided; a hit needs tMin < t < tMax with tMin = 0.
// Needs: Ray (camera.glsl), the scene buffers and params (trace.comp).

const float FLOAT_MAX = 3.402823466e+38;

const uint HIT_NONE = 0u;
const uint HIT_SPHERE = 1u;
const uint HIT_TRIANGLE = 2u;

struct Hit {
    float t;          // distance along the ray (its direction is unit length)
    uint kind;        // HIT_NONE, HIT_SPHERE or HIT_TRIANGLE
    uint index;       // which sphere or triangle
    vec3 barycentric; // triangles: weights of vertices 0, 1, 2
};

// Ray/sphere test in the numerically stable form of Haines et al., "Precision Improvements
// for Ray/Sphere Intersection", Ray Tracing Gems ch. 7 (2019): the discriminant comes from
// r^2 - |f - (f.d/a) d|^2 (no b^2 - ac cancellation) and the roots from q, c/q and q/a (no
// -b + sqrt(...) cancellation). Returns the nearer root in (0, tMax); from inside that is
// the far side.
bool intersectSphere(Ray ray, vec4 centerRadius, float tMax, out float t) {
    vec3 f = ray.origin - centerRadius.xyz;
    float a = dot(ray.direction, ray.direction);
    float b = -dot(f, ray.direction); // a t^2 - 2 b t + c = 0
    float r2 = centerRadius.w * centerRadius.w;
    vec3 l = f + (b / a) * ray.direction; // f without its component along the ray
    float discriminant = a * (r2 - dot(l, l));
    if (discriminant < 0.0) return false;
    float c = dot(f, f) - r2;
    float q = b + (b >= 0.0 ? sqrt(discriminant) : -sqrt(discriminant));
    float t0 = c / q; // NaN only for a ray grazing the sphere from a point on it
    float t1 = q / a;
    float tNear = t0 < t1 ? t0 : t1; // comparisons, not min/max, so a NaN cannot win
    float tFar = t0 < t1 ? t1 : t0;
    t = tNear > 0.0 ? tNear : tFar;
    return t > 0.0 && t < tMax;
}

// A ray prepared for the watertight triangle test: axes permuted so the dominant direction
// component is z (kx, ky, kz), and the shear that maps the direction onto +z.
struct ShearedRay {
    vec3 origin;
    uvec3 axes;  // kx, ky, kz
    vec3 shear;  // Sx, Sy, Sz
};

// Per-ray setup of the watertight test (Woop, Benthin & Wald 2013, section 3).
ShearedRay shearRay(Ray ray) {
    vec3 d = abs(ray.direction);
    uint kz = d.x > d.y ? (d.x > d.z ? 0u : 2u) : (d.y > d.z ? 1u : 2u);
    uint kx = kz == 2u ? 0u : kz + 1u;
    uint ky = kx == 2u ? 0u : kx + 1u;
    if (ray.direction[kz] < 0.0) { // keep the winding: swap kx and ky
        uint swap = kx;
        kx = ky;
        ky = swap;
    }
    float dz = ray.direction[kz];
    return ShearedRay(ray.origin, uvec3(kx, ky, kz),
                      vec3(ray.direction[kx] / dz, ray.direction[ky] / dz, 1.0 / dz));
}

// Watertight ray/triangle test of Woop, Benthin & Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013; two-sided (no backface culling). `precise` keeps the
// edge functions bit-identical for the two triangles of a shared edge, so a ray through
// the edge hits one of them. The paper's double-precision recomputation for an edge value
// of exactly 0 is left out: a 0 counts as inside for both neighbours, which still leaves
// no crack. Degenerate triangles (det == 0 or a zero cross product) are never hit.
// Returns t in (0, tMax) and the barycentric weights of vertices a, b, c.
bool intersectTriangle(ShearedRay ray, vec3 a, vec3 b, vec3 c, float tMax,
                       out float t, out vec3 barycentric) {
    uint kx = ray.axes.x, ky = ray.axes.y, kz = ray.axes.z;
    precise vec3 A = a - ray.origin;
    precise vec3 B = b - ray.origin;
    precise vec3 C = c - ray.origin;
    precise float ax = A[kx] - ray.shear.x * A[kz];
    precise float ay = A[ky] - ray.shear.y * A[kz];
    precise float bx = B[kx] - ray.shear.x * B[kz];
    precise float by = B[ky] - ray.shear.y * B[kz];
    precise float cx = C[kx] - ray.shear.x * C[kz];
    precise float cy = C[ky] - ray.shear.y * C[kz];
    precise float u = cx * by - cy * bx; // edge functions; u weighs vertex a
    precise float v = ax * cy - ay * cx;
    precise float w = bx * ay - by * ax;
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
    float det = u + v + w;
    if (det == 0.0) return false;
    t = ray.shear.z * (u * A[kz] + v * B[kz] + w * C[kz]) / det;
    if (!(t > 0.0 && t < tMax)) return false;
    // A zero-area triangle can still get det != 0 from the rounding of its sheared corners,
    // but a line has no area to hit. Checked last, so only for rays that would hit.
    if (all(equal(cross(b - a, c - a), vec3(0.0)))) return false;
    barycentric = vec3(u, v, w) / det;
    return true;
}

// The three corners of triangle i, from the index and position buffers.
void triangleCorners(uint i, out vec3 a, out vec3 b, out vec3 c) {
    a = vertexPositions[triangleVertices[3u * i]].xyz;
    b = vertexPositions[triangleVertices[3u * i + 1u]].xyz;
    c = vertexPositions[triangleVertices[3u * i + 2u]].xyz;
}

// The nearest hit along the ray over every sphere and triangle (brute-force loop). Of equal
// distances the first tested is kept: spheres first, then by index.
Hit closestHitEveryPrimitive(Ray ray) {
    Hit hit = Hit(FLOAT_MAX, HIT_NONE, 0u, vec3(0.0));
    float t;
    for (uint i = 0u; sceneHasSpheres && i < params.counts.x; ++i) {
        if (intersectSphere(ray, spheres[i], hit.t, t)) hit = Hit(t, HIT_SPHERE, i, vec3(0.0));
    }
    ShearedRay sheared = shearRay(ray);
    vec3 a, b, c, barycentric;
    for (uint i = 0u; sceneHasTriangles && i < params.counts.y; ++i) {
        triangleCorners(i, a, b, c);
        if (intersectTriangle(sheared, a, b, c, hit.t, t, barycentric)) {
            hit = Hit(t, HIT_TRIANGLE, i, barycentric);
        }
    }
    return hit;
}

// Whether anything lies on the ray with 0 < t < tMax, testing every primitive.
bool anyHitEveryPrimitive(Ray ray, float tMax) {
    float t;
    for (uint i = 0u; sceneHasSpheres && i < params.counts.x; ++i) {
        if (intersectSphere(ray, spheres[i], tMax, t)) return true;
    }
    ShearedRay sheared = shearRay(ray);
    vec3 a, b, c, barycentric;
    for (uint i = 0u; sceneHasTriangles && i < params.counts.y; ++i) {
        triangleCorners(i, a, b, c);
        if (intersectTriangle(sheared, a, b, c, tMax, t, barycentric)) return true;
    }
    return false;
}
