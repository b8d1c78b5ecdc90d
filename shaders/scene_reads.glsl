// How the kernel reads the scene inside its loops (traversal, primitive tests, bounces,
// lights): every array but the running sum. With texelReads (trace.comp) through uniform
// texel buffers, views of the same ranges as the storage bindings; else through those.
// Why: Mesa's lavapipe compiles a storage-buffer load inside control flow (every load of
// these loops) to a loop over the 8 SIMD lanes with a branch and a bounds check each, and
// a texel fetch to branch-free loads whatever the control flow: one vpgatherdd for R32, a
// 128-bit load per lane and a transpose for RGBA32 (docs/performance.md). On a GPU both are one
// memory instruction per lane; texel buffers are the classic layout for hierarchies there too. In
// fp64 the spheres and triangle corners are doubles and stay on the storage path; the other arrays
// are floats and uints in both precisions. Needs: the scene's storage bindings, texelReads and
// indexedTriangles (trace.comp).

layout(set = 0, binding = BINDING_SPHERE_TEXELS) uniform samplerBuffer sphereTexels;
layout(set = 0, binding = BINDING_CORNER_TEXELS) uniform samplerBuffer cornerTexels;
layout(set = 0, binding = BINDING_LAST_VERTEX_TEXELS) uniform usamplerBuffer lastVertexTexels;
layout(set = 0,
       binding = BINDING_TRIANGLE_VERTEX_TEXELS) uniform usamplerBuffer triangleVertexTexels;
layout(set = 0, binding = BINDING_POSITION_TEXELS) uniform samplerBuffer positionTexels;
layout(set = 0, binding = BINDING_BVH_NODE_TEXELS) uniform samplerBuffer bvhNodeTexels;
layout(set = 0, binding = BINDING_NORMAL_TEXELS) uniform samplerBuffer normalTexels;
layout(set = 0, binding = BINDING_MATERIAL_TEXELS) uniform samplerBuffer materialTexels;
layout(set = 0,
       binding = BINDING_SPHERE_MATERIAL_TEXELS) uniform usamplerBuffer sphereMaterialTexels;
layout(set = 0, binding = BINDING_LIGHT_TEXELS) uniform samplerBuffer lightTexels;
layout(set = 0, binding = BINDING_TEXCOORD_TEXELS) uniform samplerBuffer texcoordTexels;
layout(set = 0,
       binding = BINDING_MATERIAL_TEXTURE_TEXELS) uniform usamplerBuffer materialTextureTexels;
layout(set = 0, binding = BINDING_TEXTURE_PIXEL_TEXELS) uniform usamplerBuffer texturePixelTexels;

// Sphere i: centre xyz, radius w.
rvec4 fetchSphere(uint i) {
#ifndef RT_FP64
    if (texelReads) return texelFetch(sphereTexels, int(i));
#endif
    return spheres[i];
}

// Corner k (0, 1, 2) of triangle i in the corners layout: its position xyz, and in w the
// word of shared.h (BINDING_TRIANGLE_CORNERS), which cornerWord reads.
rvec4 fetchCorner(uint i, uint k) {
#ifndef RT_FP64
    if (texelReads) return texelFetch(cornerTexels, int(3u * i + k));
#endif
    return triangleCorners[3u * i + k];
}

// The uint in a corner's w: corner 0's flat patch, corner 1's and 2's vertex indices.
uint cornerWord(rvec4 corner) {
#ifdef RT_FP64
    return uint(corner.w);
#else
    return floatBitsToUint(corner.w);
#endif
}

// The vertex index of triangle i's corner 2 (those of corners 0 and 1 ride in the corners).
uint fetchLastVertex(uint i) {
    if (texelReads) return texelFetch(lastVertexTexels, int(i)).x;
    return triangleLastVertices[i];
}

// Triangle i in the indexed layout: its vertices' indices in xyz, its flat patch in w.
uvec4 fetchTriangleVertices(uint i) {
    if (texelReads) return texelFetch(triangleVertexTexels, int(i));
    return triangleVertices[i];
}

// Vertex v's position in the indexed layout.
rvec3 fetchVertexPosition(uint v) {
#ifndef RT_FP64
    if (texelReads) return texelFetch(positionTexels, int(v)).xyz;
#endif
    return vertexPositions[v].xyz;
}

// What a ray test reads of triangle i, in either layout: its corners' positions a, b, c;
// returns its flat patch.
uint fetchTriangleCorners(uint i, out rvec3 a, out rvec3 b, out rvec3 c) {
    if (indexedTriangles) {
        uvec4 triangle = fetchTriangleVertices(i);
        a = fetchVertexPosition(triangle.x);
        b = fetchVertexPosition(triangle.y);
        c = fetchVertexPosition(triangle.z);
        return triangle.w;
    }
    // Three independent fetches; the flat patch rides in corner 0's w.
    rvec4 cornerA = fetchCorner(i, 0u), cornerB = fetchCorner(i, 1u), cornerC = fetchCorner(i, 2u);
    a = cornerA.xyz;
    b = cornerB.xyz;
    c = cornerC.xyz;
    return cornerWord(cornerA);
}

// What shading reads of triangle i, in either layout: its corners' positions a, b, c and
// their vertex indices; returns its flat patch.
uint fetchShadedTriangle(uint i, out rvec3 a, out rvec3 b, out rvec3 c, out uvec3 vertices) {
    if (indexedTriangles) {
        uvec4 triangle = fetchTriangleVertices(i);
        vertices = triangle.xyz;
        a = fetchVertexPosition(triangle.x);
        b = fetchVertexPosition(triangle.y);
        c = fetchVertexPosition(triangle.z);
        return triangle.w;
    }
    rvec4 cornerA = fetchCorner(i, 0u), cornerB = fetchCorner(i, 1u), cornerC = fetchCorner(i, 2u);
    vertices = uvec3(cornerWord(cornerB), cornerWord(cornerC), fetchLastVertex(i));
    a = cornerA.xyz;
    b = cornerB.xyz;
    c = cornerC.xyz;
    return cornerWord(cornerA);
}

// Hierarchy node i: four texels, one per vec4 of GpuBvhNode.
GpuBvhNode fetchBvhNode(uint i) {
    if (texelReads) {
        int first = int(4u * i);
        return GpuBvhNode(texelFetch(bvhNodeTexels, first), texelFetch(bvhNodeTexels, first + 1),
                          texelFetch(bvhNodeTexels, first + 2),
                          texelFetch(bvhNodeTexels, first + 3));
    }
    return bvhNodes[i];
}

// Vertex v's normal as given in xyz, and in w the index of its material in materials[]
// (the uint's bits): one texel.
vec4 fetchVertexNormalAndMaterial(uint v) {
    if (texelReads) return texelFetch(normalTexels, int(v));
    return vertexNormals[v];
}

// Material i: two texels.
GpuMaterial fetchMaterial(uint i) {
    if (texelReads)
        return GpuMaterial(texelFetch(materialTexels, int(2u * i)),
                           texelFetch(materialTexels, int(2u * i + 1u)));
    return materials[i];
}

// The index into materials[] of sphere i.
uint fetchSphereMaterialIndex(uint i) {
    if (texelReads) return texelFetch(sphereMaterialTexels, int(i)).x;
    return sphereMaterials[i];
}

// Light i: two texels.
GpuLight fetchLight(uint i) {
    if (texelReads)
        return GpuLight(texelFetch(lightTexels, int(2u * i)),
                        texelFetch(lightTexels, int(2u * i + 1u)));
    return lights[i];
}

// Vertex v's texture coordinates.
vec2 fetchTexcoord(uint v) {
    if (texelReads) return texelFetch(texcoordTexels, int(v)).xy;
    return vertexTexcoords[v];
}

// Where material i's texture lies: first texel, width, height (0: none).
uvec4 fetchMaterialTexture(uint i) {
    if (texelReads) return texelFetch(materialTextureTexels, int(i));
    return materialTextures[i].placement;
}

// Texel (x, y) of the texture at placement, x and y already wrapped, as rgb in [0, 1].
vec3 fetchTexel(uvec4 placement, uint x, uint y) {
    uint i = placement.x + y * placement.y + x;
    uint packed = texelReads ? texelFetch(texturePixelTexels, int(i)).x : texturePixels[i];
    return unpackUnorm4x8(packed).rgb;
}
