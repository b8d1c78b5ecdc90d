#include "render/bindings.h"

namespace {

constexpr BindingInfo array(std::uint32_t binding, const char* name) {
    return {binding, BindingRole::SceneArray, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, name};
}

constexpr BindingInfo textureArray(std::uint32_t binding, const char* name) {
    BindingInfo info = array(binding, name);
    info.textureData = true;
    return info;
}

// R32G32B32A32, R32G32 and R32 formats (float and uint) are ones every Vulkan device
// supports for uniform texel buffers.
constexpr BindingInfo texels(std::uint32_t binding, std::uint32_t source, VkFormat format,
                             std::uint32_t texelBytes, bool doublesInFp64) {
    return {binding,
            BindingRole::SceneTexels,
            VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER,
            "",
            source,
            format,
            texelBytes,
            doublesInFp64};
}

constexpr BindingInfo own(std::uint32_t binding, BindingRole role, VkDescriptorType type,
                          const char* name) {
    return {binding, role, type, name};
}

constexpr VkFormat kVec4 = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat kUint = VK_FORMAT_R32_UINT;
constexpr VkFormat kVec2 = VK_FORMAT_R32G32_SFLOAT;
constexpr VkFormat kUvec4 = VK_FORMAT_R32G32B32A32_UINT;

constexpr std::array<BindingInfo, BINDING_COUNT> table() {
    std::array<BindingInfo, BINDING_COUNT> bindings{{
        own(BINDING_OUTPUT_IMAGE, BindingRole::OutputImage, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
            "output image"),
        array(BINDING_SPHERES, "spheres"),
        array(BINDING_SPHERE_MATERIALS, "sphere materials"),
        array(BINDING_TRIANGLE_CORNERS, "triangle corners"),
        array(BINDING_TRIANGLE_LAST_VERTICES, "triangles' last vertices"),
        array(BINDING_VERTEX_NORMALS, "vertex normals"),
        array(BINDING_MATERIALS, "materials"),
        array(BINDING_LIGHTS, "lights"),
        array(BINDING_BVH_NODES, "hierarchy nodes"),
        own(BINDING_ACCUMULATION, BindingRole::Accumulation, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
            "running sum"),
        texels(BINDING_SPHERE_TEXELS, BINDING_SPHERES, kVec4, 16, true),
        texels(BINDING_CORNER_TEXELS, BINDING_TRIANGLE_CORNERS, kVec4, 16, true),
        texels(BINDING_LAST_VERTEX_TEXELS, BINDING_TRIANGLE_LAST_VERTICES, kUint, 4, false),
        texels(BINDING_BVH_NODE_TEXELS, BINDING_BVH_NODES, kVec4, 16, false),
        texels(BINDING_NORMAL_TEXELS, BINDING_VERTEX_NORMALS, kVec4, 16, false),
        texels(BINDING_MATERIAL_TEXELS, BINDING_MATERIALS, kVec4, 16, false),
        texels(BINDING_SPHERE_MATERIAL_TEXELS, BINDING_SPHERE_MATERIALS, kUint, 4, false),
        texels(BINDING_LIGHT_TEXELS, BINDING_LIGHTS, kVec4, 16, false),
        own(BINDING_PIXEL_STORY, BindingRole::PixelStory, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
            "pixel story"),
        own(BINDING_KERNEL_STATUS, BindingRole::KernelStatus, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
            "kernel status"),
        textureArray(BINDING_VERTEX_TEXCOORDS, "texture coordinates"),
        textureArray(BINDING_MATERIAL_TEXTURES, "materials' textures"),
        textureArray(BINDING_TEXTURE_PIXELS, "texture pixels"),
        texels(BINDING_TEXCOORD_TEXELS, BINDING_VERTEX_TEXCOORDS, kVec2, 8, false),
        texels(BINDING_MATERIAL_TEXTURE_TEXELS, BINDING_MATERIAL_TEXTURES, kUvec4, 16, false),
        texels(BINDING_TEXTURE_PIXEL_TEXELS, BINDING_TEXTURE_PIXELS, kUint, 4, false),
        array(BINDING_TRIANGLE_VERTICES, "triangles' vertex indices"),
        array(BINDING_VERTEX_POSITIONS, "vertex positions"),
        texels(BINDING_TRIANGLE_VERTEX_TEXELS, BINDING_TRIANGLE_VERTICES, kUvec4, 16, false),
        texels(BINDING_POSITION_TEXELS, BINDING_VERTEX_POSITIONS, kVec4, 16, true),
    }};
    return bindings;
}

// Each entry sits at its own number, and a texel view views a scene array.
constexpr bool consistent(const std::array<BindingInfo, BINDING_COUNT>& bindings) {
    for (std::uint32_t b = 0; b < BINDING_COUNT; ++b) {
        if (bindings[b].binding != b) return false;
        if (bindings[b].role == BindingRole::SceneTexels &&
            (bindings[b].source >= BINDING_COUNT ||
             bindings[bindings[b].source].role != BindingRole::SceneArray))
            return false;
    }
    return true;
}
static_assert(consistent(table()), "kBindings: an entry out of its place, or a view of no array");

} // namespace

const std::array<BindingInfo, BINDING_COUNT> kBindings = table();

std::uint32_t bindingsOfType(VkDescriptorType type) {
    std::uint32_t count = 0;
    for (const BindingInfo& info : kBindings)
        count += info.type == type ? 1 : 0;
    return count;
}
