// Textures: a triangle's diffuse colour sampled at the hit's texture coordinates, as
// docs/models.md defines it (bilinear between the four nearest texel centres, wrapping at
// the edges; v up). The host packs them (host/packing/scene_packing.h); the CPU reference
// samples the same way in double (host/reference/reference_geometry.cpp). Compiled in only
// when sceneHasTextures (trace.comp). Filtering is done here rather than by a sampler:
// Vulkan lets a device's bilinear weights be as coarse as 1/16 (subTexelPrecisionBits 4),
// which would part the image from the reference's by more than the tests allow.
// Needs: fetchTexcoord, fetchMaterialTexture and fetchTexel (scene_reads.glsl).

// The texture's colour at uv: u across from the left edge, v up from the bottom, each
// wrapped to [0, 1); texel centres at (i + 0.5) / size.
vec3 textureColor(uvec4 placement, vec2 uv) {
    vec2 size = vec2(placement.yz);
    vec2 wrapped = uv - floor(uv);
    vec2 p = vec2(wrapped.x, 1.0 - wrapped.y) * size - 0.5;
    vec2 low = floor(p);
    vec2 f = p - low;
    // low is -1 to size - 1: the wrap adds size once.
    uvec2 lo = uvec2(ivec2(low) + ivec2(placement.yz)) % placement.yz;
    uvec2 hi = (lo + 1u) % placement.yz;
    vec3 top = mix(fetchTexel(placement, lo.x, lo.y), fetchTexel(placement, hi.x, lo.y), f.x);
    vec3 bottom = mix(fetchTexel(placement, lo.x, hi.y), fetchTexel(placement, hi.x, hi.y), f.x);
    return mix(top, bottom, f.y);
}

// The texture of material `material` at the barycentric point w of the triangle with
// vertices v, times kd; kd itself when the material has no texture.
vec3 texturedDiffuse(vec3 kd, uint material, uvec3 v, vec3 w) {
    uvec4 placement = fetchMaterialTexture(material);
    if (placement.y == 0u) return kd;
    vec2 uv = w.x * fetchTexcoord(v.x) + w.y * fetchTexcoord(v.y) + w.z * fetchTexcoord(v.z);
    return kd * textureColor(placement, uv);
}
