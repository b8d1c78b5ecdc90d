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

const float OFFSET_ORIGIN = 1.0 / 32.0;         // coordinates below s/32 get the absolute offset
const float OFFSET_FLOAT_SCALE = 1.0 / 65536.0; // absolute offset: s/65536 times n
const float OFFSET_INT_SCALE = 256.0;           // ULP offset elsewhere: 256 ULPs times n

// Moves p off its surface along the unit geometric normal n, which must point to the side
// the new ray leaves on (Waechter & Binder integer-ULP offset, scale-relative as above).
vec3 offsetRayOrigin(vec3 p, vec3 n, vec3 magnitude) {
    float scale = max(magnitude.x, max(magnitude.y, magnitude.z));
    ivec3 ulps = ivec3(OFFSET_INT_SCALE * n);
    vec3 ulpStep = intBitsToFloat(floatBitsToInt(magnitude) + ulps) - magnitude; // exact
    vec3 absoluteStep = (OFFSET_FLOAT_SCALE * scale) * n;
    return p + mix(ulpStep, absoluteStep, lessThan(magnitude, vec3(OFFSET_ORIGIN * scale)));
}
