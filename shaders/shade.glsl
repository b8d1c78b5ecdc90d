// Surface data at a hit and Phong shading with hard shadows, as docs/model.md defines them.
// Needs: Ray, Hit (camera.glsl, intersect.glsl), anyHit (bvh.glsl), offsetRayOrigin
// (ray_offset.glsl), the scene reads (scene_reads.glsl), the story's calls (pixel_story.glsl),
// texturedDiffuse (texture.glsl).

// Everything shading needs about a hit point.
struct SurfacePoint {
    rvec3 position;
    rvec3 magnitude;       // per coordinate, sum of |terms| that position was computed from
    real normalError;      // bound on position's distance from the surface along the normal
    rvec3 geometricNormal; // unit, either side: the side a new ray leaves on picks the sign
    rvec3 normal;          // unit shading normal, flipped to face the incoming ray
    vec3 kd;               // diffuse colour
    vec3 ks;               // specular colour
    vec3 kr;               // mirror weight: ks times the material's mirror share
    float shininess;       // Phong exponent
    uint flatPatch;        // the hit triangle's flat patch, or NO_PATCH for a sphere
    rvec3 shadowPoint;     // where shadow rays leave from: position, or shifted (below)
};

// Hanika's shadow terminator fix ("Hacking the Shadow Terminator", Ray Tracing Gems II,
// ch. 4): p moved, for each vertex i whose tangent plane (normal n_i, unit, facing the
// shaded side) p lies below, up onto that plane, the moves weighted by the barycentrics:
// p - sum w_i min(0, dot(p - v_i, n_i)) n_i. On a coarse smooth-shaded mesh the shadow ray
// then clears the neighbouring faces that would otherwise shadow where the smooth normal
// still faces the light; on a flat face (every n_i the face's normal) it is p itself.
rvec3 shiftedShadowPoint(rvec3 p, rvec3 w, rvec3 a, rvec3 b, rvec3 c, rvec3 na, rvec3 nb,
                         rvec3 nc) {
    real da = min(real(0.0), dot(p - a, na)), db = min(real(0.0), dot(p - b, nb)),
         dc = min(real(0.0), dot(p - c, nc));
    return p - (w.x * da * na + w.y * db * nb + w.z * dc * nc);
}

// v scaled to unit length, or fallback when v is zero (normalize(0) is NaN on lavapipe);
// dividing by the largest component first keeps tiny and huge vectors in range.
rvec3 normalizeOr(rvec3 v, rvec3 fallback) {
    real m = max(abs(v.x), max(abs(v.y), abs(v.z)));
    return m > 0.0 ? normalize(v / m) : fallback;
}

// The material of a vertex, from its normal's texel (the index rides in w).
GpuMaterial vertexMaterial(vec4 normalAndMaterial) {
    return fetchMaterial(floatBitsToUint(normalAndMaterial.w));
}

// With --offset error-bound: the hit point as the ray's own point on the triangle's plane,
// o + t d with t = dot(n, a - o) / dot(n, d), n = cross(b - a, c - a), where that is the
// tighter of the two. The barycentric sum's error grows with the vertices' magnitudes, this
// one's with the eye's and t's: on a ground 1e6 across, seen from 1 unit above it, 1e5
// times less, which keeps thin shadows where the reference has them. Each bound is pbrt-v4's
// running error analysis (section 6.8): n carries gamma(4) of the cross product of the
// edges' magnitudes, the dot products gamma(4) and gamma(5) of their terms' magnitudes, the
// point gamma(3) of |o| + |t d| plus d times t's error; along the normal, t's error counts
// only times the cosine of the incidence, (err(num) + |t| err(den)) / |n| (derived in
// docs/accuracy.md).
// a is a corner, e1 and e2 the edges from it, n = cross(e1, e2) (surfaceAt's, unnormalised).
void onTrianglePlane(Ray ray, rvec3 a, rvec3 e1, rvec3 e2, rvec3 n, inout SurfacePoint s) {
    real nLength = length(n);
    real den = dot(n, ray.direction);
    if (!(nLength > 0.0) || den == 0.0) return; // edge-on: keep the barycentric point
    rvec3 toA = a - ray.origin;
    real t = dot(n, toA) / den;
    rvec3 p = ray.origin + t * ray.direction;
    rvec3 nError = GAMMA_4 * (abs(e1.yzx * e2.zxy) + abs(e1.zxy * e2.yzx));
    real numError = GAMMA_5 * dot(abs(n), abs(toA)) + dot(nError, abs(toA));
    real denError = GAMMA_4 * dot(abs(n), abs(ray.direction)) + dot(nError, abs(ray.direction));
    real tError = (numError + abs(t) * denError) / abs(den);
    rvec3 rounding = GAMMA_3 * (abs(ray.origin) + abs(t * ray.direction));
    rvec3 pError = rounding + abs(ray.direction) * tError;
    rvec3 barycentricError = GAMMA_7 * s.magnitude;
    if (pError.x + pError.y + pError.z >=
        barycentricError.x + barycentricError.y + barycentricError.z)
        return;
    s.position = p;
    s.normalError =
        dot(abs(s.geometricNormal), rounding) + (numError + abs(t) * denError) / nLength;
}

// Position, normals and material at a hit. Sphere: N = (P - C) / r, with P projected back
// onto the sphere; triangle: P, the vertex normals and the materials interpolated with
// the barycentrics, the geometric normal normalize(cross(B - A, C - A)) when the
// interpolated normal is zero.
SurfacePoint surfaceAt(Ray ray, Hit hit) {
    SurfacePoint s;
    if (sceneHasSpheres && (!sceneHasTriangles || hit.kind == HIT_SPHERE)) {
        rvec4 sphere = fetchSphere(hit.index);
        rvec3 radial = normalizeOr(ray.origin + hit.t * ray.direction - sphere.xyz, -ray.direction);
        s.position = sphere.xyz + sphere.w * radial;
        s.magnitude = abs(sphere.xyz) + sphere.w * abs(radial);
        s.geometricNormal = radial;
        s.normalError = dot(abs(radial), GAMMA_7 * s.magnitude);
        s.normal = radial;
        GpuMaterial m = fetchMaterial(fetchSphereMaterialIndex(hit.index));
        s.kd = m.diffuseShininess.xyz;
        s.ks = m.specular.xyz;
        s.kr = sceneHasMirrorShares ? s.ks * m.specular.w : s.ks;
        s.shininess = m.diffuseShininess.w;
        s.flatPatch = NO_PATCH;
        s.shadowPoint = s.position;
    } else {
        rvec3 a, b, c;
        uvec3 v;
        s.flatPatch = fetchShadedTriangle(hit.index, a, b, c, v);
        rvec3 w = hit.barycentric;
        // The barycentric sum, whose error scales with the vertices only; with --offset
        // error-bound, onTrianglePlane takes o + t d instead where that bound is tighter.
        s.position = w.x * a + w.y * b + w.z * c;
        s.magnitude = w.x * abs(a) + w.y * abs(b) + w.z * abs(c);
        rvec3 e1 = b - a, e2 = c - a;
        rvec3 faceNormal = cross(e1, e2);
        s.geometricNormal = normalizeOr(faceNormal, -ray.direction);
        s.normalError = dot(abs(s.geometricNormal), GAMMA_7 * s.magnitude);
        if (rayOffsetKind == RAY_OFFSET_ERROR_BOUND) onTrianglePlane(ray, a, e1, e2, faceNormal, s);
        vec4 va = fetchVertexNormalAndMaterial(v.x), vb = fetchVertexNormalAndMaterial(v.y),
             vc = fetchVertexNormalAndMaterial(v.z);
        rvec3 n = w.x * rvec3(va.xyz) + w.y * rvec3(vb.xyz) + w.z * rvec3(vc.xyz);
        s.normal = normalizeOr(n, s.geometricNormal);
        GpuMaterial ma = vertexMaterial(va);
        GpuMaterial mb = vertexMaterial(vb);
        GpuMaterial mc = vertexMaterial(vc);
        vec3 wf = vec3(w); // colours stay float
        vec4 kdShininess =
            wf.x * ma.diffuseShininess + wf.y * mb.diffuseShininess + wf.z * mc.diffuseShininess;
        s.kd = kdShininess.xyz;
        if (sceneHasTextures) // a triangle's corners share its material's texture
            s.kd = texturedDiffuse(s.kd, floatBitsToUint(va.w), v, wf);
        s.shininess = kdShininess.w;
        s.ks = wf.x * ma.specular.xyz + wf.y * mb.specular.xyz + wf.z * mc.specular.xyz;
        // Interpolated as the reference does: each corner's ks times its share.
        s.kr = sceneHasMirrorShares ? wf.x * (ma.specular.xyz * ma.specular.w) +
                                          wf.y * (mb.specular.xyz * mb.specular.w) +
                                          wf.z * (mc.specular.xyz * mc.specular.w)
                                    : s.ks;
        s.shadowPoint = s.position;
        if (shiftShadowOrigin) {
            // The vertex normals, unit, on the side the shading normal faces once flipped.
            real facing = dot(s.normal, ray.direction) > 0.0 ? real(-1.0) : real(1.0);
            s.shadowPoint = shiftedShadowPoint(
                s.position, w, a, b, c, facing * normalizeOr(rvec3(va.xyz), s.geometricNormal),
                facing * normalizeOr(rvec3(vb.xyz), s.geometricNormal),
                facing * normalizeOr(rvec3(vc.xyz), s.geometricNormal));
        }
    }
    if (dot(s.normal, ray.direction) > 0.0) s.normal = -s.normal;
    return s;
}

// A ray from the surface point in direction d (unit), its origin offset to the side of the
// surface d leaves on, so it cannot hit the surface it starts from (ray_offset.glsl).
Ray leavingRay(SurfacePoint s, rvec3 d) {
    rvec3 side = dot(s.geometricNormal, d) > 0.0 ? s.geometricNormal : -s.geometricNormal;
    return Ray(offsetRayOrigin(s.position, side, s.magnitude, s.normalError), d, s.flatPatch);
}

// Whether any surface lies strictly between the point and the light (unit direction l):
// an any-hit shadow ray from the offset origin, limited to the distance to the light.
bool inShadow(SurfacePoint s, rvec3 lightPosition, rvec3 l) {
    Ray ray = leavingRay(s, l);
    if (shiftShadowOrigin) {
        rvec3 side = dot(s.geometricNormal, l) > 0.0 ? s.geometricNormal : -s.geometricNormal;
        ray.origin = offsetRayOrigin(s.shadowPoint, side, s.magnitude, s.normalError);
    }
    rvec3 toLight = lightPosition - ray.origin;
    real lightDistance = length(toLight);
    ray.direction = toLight / lightDistance;
    bool blocked = anyHit(ray, shadowRayLength(ray.origin, lightPosition, lightDistance));
    if (blocked && storyRecording()) storyShadowBlocker(closestHit(ray)); // pixel_story.glsl
    return blocked;
}

// Local Phong colour seen along direction -view: ambient once, then per unshadowed light
// in front of the surface Lc * (kd dot(N,L) + ks max(dot(R,V),0)^shininess).
// The highlight is compiled out when no material has ks > 0 (sceneHasSpecular, trace.comp;
// it would add exactly 0).
vec3 shadePhong(SurfacePoint s, rvec3 view) {
    vec3 color = params.ambient.rgb;
    uint i = 0u;
    if (lightCount > 0u) { // do-while: see traverseBvh (bvh.glsl)
        do {
            GpuLight light = fetchLight(i);
            rvec3 lightPosition = light.position.xyz;
            // A light exactly at the point has no direction: l = 0 skips it below.
            rvec3 l = normalizeOr(lightPosition - s.position, rvec3(0.0));
            real nDotL = dot(s.normal, l);
            if (nDotL <= 0.0) {
                storyLight(i, STORY_LIGHT_BEHIND, float(nDotL), vec3(0.0)); // pixel_story.glsl
                continue;
            }
            if (inShadow(s, lightPosition, l)) {
                storyLight(i, STORY_LIGHT_BLOCKED, float(nDotL), vec3(0.0));
                continue;
            }
            vec3 diffuse = s.kd * float(nDotL);
            if (!sceneHasSpecular) {
                vec3 share = light.color.rgb * diffuse;
                storyLight(i, STORY_LIGHT_LIT, float(nDotL), share);
                color += share;
                continue;
            }
            rvec3 r = 2.0 * nDotL * s.normal - l;
            float rDotV = float(dot(r, view));
            // pow(x, 0) is 1 for x > 0; the test keeps pow away from 0 and negative bases.
            vec3 specular = rDotV > 0.0 ? s.ks * pow(rDotV, s.shininess) : vec3(0.0);
            vec3 share = light.color.rgb * (diffuse + specular);
            storyLight(i, STORY_LIGHT_LIT, float(nDotL), share);
            color += share;
        } while (++i < lightCount);
    }
    return color;
}

// The mirror ray at the surface: direction D - 2 dot(D, N) N with the facing shading normal.
Ray reflectedRay(Ray ray, SurfacePoint s) {
    return leavingRay(s, normalize(reflect(ray.direction, s.normal)));
}
