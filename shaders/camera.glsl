// Primary rays (the SPEC's pinhole camera) and the sample positions inside a pixel.
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
    vec3 origin;
    vec3 direction; // unit length
};

// v rotated by the unit quaternion q (xyz vector part, w scalar part). For the identity
// (0,0,0,1) both cross products are exactly zero, so v comes back bit for bit.
vec3 rotateByQuaternion(vec4 q, vec3 v) {
    return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

// The primary ray through the point (u, v) of pixel (i, j): the SPEC's camera formula in
// camera space, then placed in the world by params.cameraOrigin and cameraOrientation
// (--camera-pos/-target/-up). The direction is rotated before it is normalised, so the
// SPEC camera (identity, origin 0) gives exactly the SPEC's rays.
Ray cameraRay(uvec2 pixel, vec2 uv) {
    vec2 size = vec2(params.image.xy);
    vec2 ndc = vec2(2.0 * (float(pixel.x) + uv.x) / size.x - 1.0,
                    1.0 - 2.0 * (float(pixel.y) + uv.y) / size.y);
    vec3 direction = rotateByQuaternion(params.cameraOrientation, vec3(ndc * params.camera.xy, -1.0));
    return Ray(params.cameraOrigin.xyz, normalize(direction));
}

// Integer hash "lowbias32" (Chris Wellons, hash-prospector): a well-mixed 32-bit permutation.
uint hashUint(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// The most nearly square grid of exactly n cells: rows is the largest divisor of n that
// is at most sqrt(n), so every cell has the same area (a prime n gives 1 x n strips).
uvec2 stratumGrid(uint n) {
    uint rows = uint(sqrt(float(n)));
    while (rows * rows > n) rows--;
    while ((rows + 1u) * (rows + 1u) <= n) rows++;
    while (n % rows != 0u) rows--;
    return uvec2(n / rows, rows); // (columns, rows)
}

// Offset (u, v) of sample s of n in a pixel: the centre for n == 1, otherwise stratified
// jittered sampling, one sample per cell with a deterministic jitter hashed from (pixel, s).
vec2 sampleOffset(uvec2 pixel, uint s, uint n) {
    if (n <= 1u) return vec2(0.5);
    uvec2 grid = stratumGrid(n);
    uvec2 cell = uvec2(s % grid.x, s / grid.x);
    uint h1 = hashUint(hashUint(hashUint(pixel.x) ^ pixel.y) ^ s);
    uint h2 = hashUint(h1);
    vec2 jitter = vec2(h1 >> 8, h2 >> 8) * (1.0 / 16777216.0); // 24 bits, in [0, 1)
    return min((vec2(cell) + jitter) / vec2(grid), vec2(0.99999994)); // rounding may reach 1
}
