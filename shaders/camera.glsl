// Primary rays (the pinhole camera of docs/model.md); sample positions inside a pixel:
// sampling.glsl.
//
//            +y
//             ^        image plane z = -1, eye at the origin looking down -z
//   pixel (0,0)                   x spans [-camera.x, +camera.x] = aspect * tan(fov/2)
//        +----|----+              y spans [-camera.y, +camera.y] = tan(fov/2)
//        |    |    |              pixel (i, j): column i from the left, row j from the top;
//   -----|----o----|----> +x      (u, v) in [0,1)^2 is the sample's offset inside it
//        |    |    |
//        +----|----+ pixel (W-1,H-1)
//
//   x = (2 (i + u) / W - 1) * camera.x,  y = (1 - 2 (j + v) / H) * camera.y,
//   direction = normalize(x, y, -1)

// What a ray leaves: no flat patch (NO_PATCH: primary rays and rays leaving a sphere), or
// the flat patch of the triangle it leaves, whose triangles its tests skip with --offset
// error-bound (a plane cannot be met again by a ray leaving it; ray_offset.glsl,
// intersectTriangle).
const uint NO_PATCH = 0xffffffffu;

struct Ray {
    rvec3 origin;    // real: float, or double with --precision fp64 (precision.glsl)
    rvec3 direction; // unit length
    uint leaving;    // the flat patch the ray leaves, or NO_PATCH
};

// v rotated by the unit quaternion q (xyz vector part, w scalar part). For the identity
// (0,0,0,1) both cross products are exactly zero, so v comes back bit for bit.
vec3 rotateByQuaternion(vec4 q, vec3 v) {
    return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

// The primary ray through the point (u, v) of pixel (i, j): the camera formula of docs/model.md in
// camera space, then placed in the world by params.cameraOrigin and cameraOrientation
// (--camera-pos/-target/-up). The direction is rotated before it is normalised, so the
// default camera (identity, origin 0) gives exactly the rays of docs/model.md.
Ray cameraRay(uvec2 pixel, vec2 uv) {
    vec2 size = vec2(params.image.xy);
    vec2 ndc = vec2(2.0 * (float(pixel.x) + uv.x) / size.x - 1.0,
                    1.0 - 2.0 * (float(pixel.y) + uv.y) / size.y);
    vec3 direction =
        rotateByQuaternion(params.cameraOrientation, vec3(ndc * params.camera.xy, -1.0));
    return Ray(params.cameraOrigin.xyz, normalize(direction), NO_PATCH);
}
