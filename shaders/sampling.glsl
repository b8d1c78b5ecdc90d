// Sample positions inside a pixel (--spp N, --sampler, --seed). One sample per pixel is
// always the pixel's centre (docs/model.md). With N > 1, sampleOffset(pixel, s, N) is sample s:
//  - grid:       the centre of cell s of the most nearly square grid of exactly N cells;
//  - stratified: a jittered point in that cell, the jitter hashed from (pixel, s, seed);
//  - r2:         point s of Roberts' R2 sequence ("The Unreasonable Effectiveness of
//                Quasirandom Sequences", 2018), shifted by a per-pixel random rotation
//                (Cranley & Patterson 1976) hashed from (pixel, seed). Point s does not
//                depend on N, so the first k samples of an N-sample render are the k-sample
//                render for every k from 2: a progressive display shows the headless --spp k
//                image at each such k on its way to --spp N (and shows the one-sample image,
//                the centre, first: host/window/present.cpp). Sample 0 is not the centre:
//                that costs 3-23% more error at 4 to 16 samples (docs/accuracy.md).
// Needs: params (seed in counts.w) and the samplerKind specialization constant (trace.comp).

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
    while (rows * rows > n)
        rows--;
    while ((rows + 1u) * (rows + 1u) <= n)
        rows++;
    while (n % rows != 0u)
        rows--;
    return uvec2(n / rows, rows); // (columns, rows)
}

// 32-bit fractions in [0, 1) as floats: the top 24 bits, so the result stays below 1.
vec2 unitFromBits(uvec2 bits) {
    return vec2(bits >> 8u) * (1.0 / 16777216.0);
}

// R2's two generators 1/g and 1/g^2 (g = 1.3247179572..., the plastic number) as 32-bit
// fixed-point fractions: point s is s * alpha mod 1, computed exactly in integers (a float
// product would lose the fraction's low bits once s reaches the thousands).
const uvec2 R2_ALPHA = uvec2(3242174889u, 2447445413u);

vec2 sampleOffset(uvec2 pixel, uint s, uint n) {
    if (n <= 1u) return vec2(0.5);
    uint seed = params.counts.w;
    if (samplerKind == SAMPLER_R2) {
        uint h1 = hashUint(hashUint(hashUint(pixel.x) ^ pixel.y) ^ hashUint(seed ^ 0x52325232u));
        uvec2 rotation = uvec2(h1, hashUint(h1));
        return unitFromBits(rotation + s * R2_ALPHA); // wraps mod 2^32: mod 1 exactly
    }
    uvec2 grid = stratumGrid(n);
    uvec2 cell = uvec2(s % grid.x, s / grid.x);
    if (samplerKind == SAMPLER_GRID) return (vec2(cell) + 0.5) / vec2(grid);
    uint h1 = hashUint(hashUint(hashUint(pixel.x) ^ pixel.y) ^ s);
    if (seed != 0u) h1 = hashUint(h1 ^ hashUint(seed)); // seed 0: the jitter of earlier versions
    uint h2 = hashUint(h1);
    vec2 jitter = unitFromBits(uvec2(h1, h2));
    return min((vec2(cell) + jitter) / vec2(grid), vec2(0.99999994)); // rounding may reach 1
}
