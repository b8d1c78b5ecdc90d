// Self-intersection avoidance for secondary rays (shadow and reflection rays).
//
// Method: Waechter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection",
// Ray Tracing Gems, ch. 6 (2019), with the paper's constants, made scale-relative in two
// places so that it holds from 1e-4 to 1e5 (tested by rendering the sample scenes scaled):
//  - The paper offsets each coordinate by 256 ULPs of itself. Here the ULPs are those of
//    `magnitude`, the per-coordinate sum of the absolute terms the point was computed from
//    (|p| itself when the point lies near its vertices), because that bounds the rounding
//    error: a point near the origin on a huge triangle is only as accurate as the
//    triangle's far vertices (the floor of snow.scene shows acne otherwise).
//  - Coordinates too close to zero for ULPs to help get an absolute offset. The paper uses
//    1/65536 below 1/32, which is far too big for a scene 1e-4 across; here both are
//    relative to the point's scale s (its largest magnitude), i.e. the paper's values at
//    s = 1. Intersection tests mix coordinates (the watertight shear), so a coordinate near
//    zero still carries rounding error of order s.
// In fp64 (precision.glsl) the same numbers of ULPs, of doubles. --offset fixed swaps all of
// this for the textbook fixed epsilon (specialization constant scaledRayOffset, trace.comp).

const float OFFSET_ORIGIN = 1.0 / 32.0; // coordinates below s/32 get the absolute offset
const float OFFSET_INT_SCALE = 256.0;   // ULP offset elsewhere: 256 ULPs times n
#ifdef RT_FP64
// Absolute offset: s times n times the same 128 ULPs of 1 as in float (2^-16 = 128 * 2^-23),
// now of a double: 128 * 2^-52.
const double OFFSET_FLOAT_SCALE = 2.8421709430404007e-14LF;
#else
const float OFFSET_FLOAT_SCALE = 1.0 / 65536.0; // absolute offset: s/65536 times n
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
#else
vec3 ulpSteps(vec3 magnitude, vec3 n) {
    ivec3 ulps = ivec3(OFFSET_INT_SCALE * n);
    return intBitsToFloat(floatBitsToInt(magnitude) + ulps) - magnitude; // exact
}
#endif

// Moves p off its surface along the unit geometric normal n, which must point to the side
// the new ray leaves on (Waechter & Binder integer-ULP offset, scale-relative as above; or,
// with --offset fixed, FIXED_OFFSET along n).
rvec3 offsetRayOrigin(rvec3 p, rvec3 n, rvec3 magnitude) {
    if (!scaledRayOffset) return p + FIXED_OFFSET * n;
    real scale = max(magnitude.x, max(magnitude.y, magnitude.z));
    rvec3 ulpStep = ulpSteps(magnitude, n);
    rvec3 absoluteStep = (OFFSET_FLOAT_SCALE * scale) * n;
    return p + mix(ulpStep, absoluteStep, lessThan(magnitude, rvec3(OFFSET_ORIGIN * scale)));
}
