// How the kernel reads the scene inside its loops (traversal, primitive tests, bounces,
// lights): every array but the running sum. With texelReads (trace.comp) through uniform
// texel buffers, views of the same ranges as the storage bindings; else through those.
// Why: Mesa's lavapipe compiles a storage-buffer load inside control flow (every load of
// these loops) to a loop over the 8 SIMD lanes with a branch and a bounds check each, and
// a texel fetch to one gather, whatever the control flow. On a GPU both are one memory
// instruction per lane; texel buffers are the classic layout for hierarchies there too.
// In fp64 the spheres and vertex positions are doubles and stay on the storage path; the
// other arrays are floats and uints in both precisions.
// Needs: the scene's storage bindings and texelReads (trace.comp).

layout(set = 0, binding = BINDING_SPHERE_TEXELS) uniform samplerBuffer sphereTexels;
layout(set = 0, binding = BINDING_TRIANGLE_TEXELS) uniform usamplerBuffer triangleTexels;
layout(set = 0, binding = BINDING_POSITION_TEXELS) uniform samplerBuffer positionTexels;
layout(set = 0, binding = BINDING_BVH_NODE_TEXELS) uniform samplerBuffer bvhNodeTexels;
layout(set = 0, binding = BINDING_NORMAL_TEXELS) uniform samplerBuffer normalTexels;
layout(set = 0, binding = BINDING_MATERIAL_TEXELS) uniform samplerBuffer materialTexels;
layout(set = 0,
       binding = BINDING_SPHERE_MATERIAL_TEXELS) uniform usamplerBuffer sphereMaterialTexels;
layout(set = 0, binding = BINDING_LIGHT_TEXELS) uniform samplerBuffer lightTexels;

// Sphere i: centre xyz, radius w.
rvec4 fetchSphere(uint i) {
#ifndef RT_FP64
    if (texelReads) return texelFetch(sphereTexels, int(i));
#endif
    return spheres[i];
}

// Triangle i: its three vertex indices in xyz, its flat patch in w.
uvec4 fetchTriangle(uint i) {
    if (texelReads) return texelFetch(triangleTexels, int(i));
    return triangles[i];
}

// The position of vertex v.
rvec3 fetchPosition(uint v) {
#ifndef RT_FP64
    if (texelReads) return texelFetch(positionTexels, int(v)).xyz;
#endif
    return vertexPositions[v].xyz;
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

// The index into materials[] of vertex v: it rides in the position's w, as the float's bits
// (fp32) or as a double's exact integer value (fp64).
uint fetchVertexMaterialIndex(uint v) {
#ifdef RT_FP64
    return uint(vertexPositions[v].w);
#else
    if (texelReads) return floatBitsToUint(texelFetch(positionTexels, int(v)).w);
    return floatBitsToUint(vertexPositions[v].w);
#endif
}

// The normal of vertex v as given (three packed floats).
vec3 fetchNormal(uint v) {
    if (texelReads) {
        int first = int(3u * v);
        return vec3(texelFetch(normalTexels, first).x, texelFetch(normalTexels, first + 1).x,
                    texelFetch(normalTexels, first + 2).x);
    }
    return vec3(vertexNormals[3u * v], vertexNormals[3u * v + 1u], vertexNormals[3u * v + 2u]);
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
