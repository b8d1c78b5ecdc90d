// The kernel's descriptor bindings in one table: what each binding number of shaders/shared.h
// is (its descriptor type, what fills it, its name in messages, and for a texel view the
// storage binding it views and its format). The pipeline layout, the descriptor pool and
// writes (renderer.cpp) and the scene upload (scene_upload.cpp) all read it, rather than
// inferring a binding's kind from where its number falls.
#pragma once

#include "shared.h"

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>

// What fills a binding.
enum class BindingRole {
    OutputImage,  // the image the kernel writes (resizeOutput)
    SceneArray,   // a range of the scene buffer (scene_upload.h)
    SceneTexels,  // a texel view of a SceneArray's range (scene_upload.h)
    Accumulation, // the window's running sum (resizeOutput)
    PixelStory,   // the recording kernel's story (renderer.cpp)
    KernelStatus, // what the kernel reports of its run (renderer.cpp)
};

struct BindingInfo {
    std::uint32_t binding = 0;
    BindingRole role = BindingRole::SceneArray;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const char* name = ""; // in messages: "the scene's hierarchy nodes take ..."
    // SceneTexels only: the SceneArray viewed, the texel format and size, and whether fp64
    // reads that array's doubles through its storage binding instead.
    std::uint32_t source = 0;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::uint32_t texelBytes = 0;
    bool doublesInFp64 = false;
    // SceneArray only: the array holds texture data (texels, placements, coordinates), which
    // the scene memory line and --bench report apart (GpuScene::textureBytes).
    bool textureData = false;
};

// Every binding, indexed by its number.
extern const std::array<BindingInfo, BINDING_COUNT> kBindings;

// How many bindings have this descriptor type (the descriptor pool's sizes).
std::uint32_t bindingsOfType(VkDescriptorType type);
