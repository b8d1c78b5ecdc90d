// Self-intersection avoidance for secondary rays (shadow and reflection rays), three ways
// (--offset, the specialization constant rayOffsetKind, trace.comp); derived and measured
// in docs/accuracy.md.
//
// error-bound (not yet the default, docs/accuracy.md): the origin moves along the geometric normal
// by the bound on the hit point's rounding error, projected on the normal, and rounds away from the
// surface (Pharr, Jakob & Humphreys, pbrt-v4, section 6.8). A point computed as
// sum b_i p_i (a triangle) or c + r n (a sphere) has, per coordinate, an error below
// gamma(7) times the sum of the absolute terms that coordinate was computed from:
// `magnitude`, so a coordinate is moved only as far as its own arithmetic can be off, and
// a large x beside a small y does not lift the point in y. The flat patch of the triangle
// the ray leaves (its coplanar neighbours; host/packing/flat_patches.h) is skipped by its
// tests (Ray.leaving): a ray leaving a plane cannot meet it again, and the triangle test's
// own error (which grows with the vertices' distance from the origin, not with the
// point's) then cannot bring it back, for the triangle itself or for the other half of a
// quad. A sphere needs no such skip: with the origin outside (or inside) it by the bound,
// the stable test's roots keep their sign.
//
// scaled: Waechter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection",
// Ray Tracing Gems, ch. 6 (2019), made scale-relative: 256 ULPs of `magnitude` per
// coordinate, and coordinates below s/32 (s: the point's largest magnitude) an absolute
// s/65536. It lifts a point on a huge ground by s/65536 whatever its height's own error:
// 1.5 units on a ground 2e5 across, above lights that stand lower (the stress family
// ground_* fails with it).
//
// fixed: the textbook 1e-4 along the normal, whatever the scene's scale.
//
// In fp64 (precision.glsl) the same bounds and ULP counts, of doubles.

const float OFFSET_ORIGIN = 1.0 / 32.0; // scaled: coordinates below s/32 get the absolute offset
const float OFFSET_INT_SCALE = 256.0;   // scaled: 256 ULPs times n elsewhere
#ifdef RT_FP64
// Absolute offset: s times n times the same 128 ULPs of 1 as in float (2^-16 = 128 * 2^-23),
// now of a double: 128 * 2^-52.
const double OFFSET_FLOAT_SCALE = 2.8421709430404007e-14LF;
// gamma(n) = n u / (1 - n u) with the unit roundoff u = 2^-53, rounded up: a bound on the
// relative error of n roundings (pbrt-v4, section 6.8.1).
const double GAMMA_3 = 3.330669073875471e-16LF;
const double GAMMA_4 = 4.440892098500629e-16LF;
const double GAMMA_5 = 5.551115123125787e-16LF;
const double GAMMA_7 = 7.771561172376103e-16LF;
#else
const float OFFSET_FLOAT_SCALE = 1.0 / 65536.0; // absolute offset: s/65536 times n
// gamma(n) = n u / (1 - n u) with u = 2^-24, rounded up.
const float GAMMA_3 = 1.78813977e-7;
const float GAMMA_4 = 2.38418664e-7;
const float GAMMA_5 = 2.98023338e-7;
const float GAMMA_7 = 4.1723284e-7;
#endif
// --offset fixed: the textbook epsilon, in scene units whatever the scene's scale.
const float FIXED_OFFSET = 1e-4;

// Per coordinate, the step from magnitude to the value trunc(256 n) ULPs away (exact).
#ifdef RT_FP64
// In double through the exponent bits (no 64-bit integers needed): ulp(m) = 2^(E - 52)
// for m = 1.f * 2^E, 0 for 0 and subnormals (below s/32 anyway, so not used).
double ulpOf(double m) {
    return packDouble2x32(uvec2(0u, unpackDouble2x32(m).y & 0x7ff00000u)) * 2.220446049250313e-16LF;
}
dvec3 ulpSteps(dvec3 magnitude, dvec3 n) {
    return trunc(OFFSET_INT_SCALE * n) *
           dvec3(ulpOf(magnitude.x), ulpOf(magnitude.y), ulpOf(magnitude.z));
}
// The neighbour of x in the direction of away's sign (x itself where away == 0): one ULP
// up or down through the bits, +-0 to the smallest subnormal of that sign.
dvec3 stepAway(dvec3 x, dvec3 away) {
    dvec3 result = x;
    for (int k = 0; k < 3; ++k) {
        if (away[k] == 0.0) continue;
        uvec2 bits = unpackDouble2x32(x[k]);
        bool grows = (away[k] > 0.0) == (x[k] >= 0.0); // the magnitude, that is
        if (x[k] == 0.0)
            bits = uvec2(1u, away[k] > 0.0 ? 0u : 0x80000000u);
        else if (grows) {
            uint carry;
            bits.x = uaddCarry(bits.x, 1u, carry);
            bits.y += carry;
        } else {
            uint borrow;
            bits.x = usubBorrow(bits.x, 1u, borrow);
            bits.y -= borrow;
        }
        result[k] = packDouble2x32(bits);
    }
    return result;
}
#else
vec3 ulpSteps(vec3 magnitude, vec3 n) {
    ivec3 ulps = ivec3(OFFSET_INT_SCALE * n);
    return intBitsToFloat(floatBitsToInt(magnitude) + ulps) - magnitude; // exact
}
// The neighbour of x in the direction of away's sign (x itself where away == 0): one ULP
// up or down through the bits, +-0 to the smallest subnormal of that sign.
vec3 stepAway(vec3 x, vec3 away) {
    ivec3 bits = floatBitsToInt(x);
    bvec3 grows = equal(greaterThan(away, vec3(0.0)), greaterThanEqual(x, vec3(0.0)));
    ivec3 stepped = bits + mix(ivec3(-1), ivec3(1), grows);
    ivec3 fromZero = mix(ivec3(int(0x80000001u)), ivec3(1), greaterThan(away, vec3(0.0)));
    stepped = mix(stepped, fromZero, equal(x, vec3(0.0)));
    return mix(x, intBitsToFloat(stepped), notEqual(away, vec3(0.0)));
}
#endif

// Moves p off its surface along the unit geometric normal n, which must point to the side
// the new ray leaves on, by the method --offset chose (above): error-bound by normalError,
// the bound on p's distance from the surface along n (shade.glsl, surfaceAt).
rvec3 offsetRayOrigin(rvec3 p, rvec3 n, rvec3 magnitude, real normalError) {
    if (rayOffsetKind == RAY_OFFSET_FIXED) return p + FIXED_OFFSET * n;
    if (rayOffsetKind == RAY_OFFSET_ERROR_BOUND) {
        rvec3 offset = normalError * n;
        // The sum rounds to nearest: one more ULP away from the surface keeps it there.
        return stepAway(p + offset, offset);
    }
    real scale = max(magnitude.x, max(magnitude.y, magnitude.z));
    rvec3 ulpStep = ulpSteps(magnitude, n);
    rvec3 absoluteStep = (OFFSET_FLOAT_SCALE * scale) * n;
    return p + mix(ulpStep, absoluteStep, lessThan(magnitude, rvec3(OFFSET_ORIGIN * scale)));
}

// The distance a shadow ray from origin may run towards a light at lightDistance: the
// whole way, less (with --offset error-bound) the bound on where the ray's far end lands,
// so that a surface the light stands a hair above does not shadow it through rounding.
real shadowRayLength(rvec3 origin, rvec3 lightPosition, real lightDistance) {
    if (rayOffsetKind != RAY_OFFSET_ERROR_BOUND) return lightDistance;
    rvec3 reach = abs(origin) + abs(lightPosition);
    return lightDistance - GAMMA_7 * (max(reach.x, max(reach.y, reach.z)) + lightDistance);
}
