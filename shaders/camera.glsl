// Primary rays (the SPEC's pinhole camera); sample positions inside a pixel: sampling.glsl.
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

struct Ray {
    rvec3 origin;    // real: float, or double with --precision fp64 (precision.glsl)
    rvec3 direction; // unit length
};

// The primary ray through the point (u, v) of pixel (i, j), the SPEC's camera formula.
Ray cameraRay(uvec2 pixel, vec2 uv) {
    vec2 size = vec2(params.image.xy);
    vec2 ndc = vec2(2.0 * (float(pixel.x) + uv.x) / size.x - 1.0,
                    1.0 - 2.0 * (float(pixel.y) + uv.y) / size.y);
    return Ray(vec3(0.0), normalize(vec3(ndc * params.camera.xy, -1.0)));
}
