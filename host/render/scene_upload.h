// The packed scene in device buffers, each binding seeing its own range.
#pragma once

#include "gpu/resources.h"
#include "packing/scene_packing.h"

#include <string>
#include <vector>

// The scene's arrays, one after another in as few device buffers as the device's
// maxMemoryAllocationSize allows (one for any but the largest scenes), each buffer starting
// with a zeroed 16-byte slot that empty arrays bind; each binding sees its own range.
struct GpuScene {
    std::vector<Buffer> buffers;
    VkDescriptorBufferInfo ranges[BINDING_COUNT]{}; // BINDING_OUTPUT_IMAGE's entry unused
    VkDeviceSize bytes = 0;                         // device memory holding the scene
    VkDeviceSize textureBytes = 0; // of which textures: texels, placements, texture coordinates
    std::uint32_t sphereCount = 0;
    std::uint32_t triangleCount = 0;
    std::uint32_t lightCount = 0;
    glm::vec4 ambient{0.0f};
    // By binding number, for the uniform texel buffer bindings (render/bindings.h's
    // SceneTexels), always valid: over the hot arrays when texelReads, else over the zeroed
    // slot (the kernel then never reads them). The other entries stay null.
    VkBufferView texelViews[BINDING_COUNT]{};
    bool texelReads = false;       // the kernel reads the hot arrays through texelViews
    bool indexedTriangles = false; // the triangles' layout (packing/triangle_layout.h)
    std::string storageReadsNote;  // why not, when an array exceeds maxTexelBufferElements
};

// How the arrays are to be read: through texel views where they can (else storage
// bindings alone), and the triangles' layout.
struct UploadLayout {
    bool texelReads = true;
    bool indexedTriangles = false; // packing/triangle_layout.h; else corners
};

// With layout.texelReads the arrays also get texel-buffer views (but fp64's doubles), unless
// one exceeds maxTexelBufferElements (storageReadsNote). An array beyond
// maxStorageBufferRange is read through its view alone; throws with the limit's name and the
// device's when one is not read so, or when one exceeds maxMemoryAllocationSize.
GpuScene uploadScene(const Context& context, const PackedScene& packed, UploadLayout layout = {});

// The same, each of packed's arrays released as soon as the arrays made of it are written:
// a large scene's packed copy is then not held whole beside the device's (lavapipe's device
// memory is the host's) or a staging buffer. packed is left empty.
GpuScene uploadScene(const Context& context, PackedScene&& packed, UploadLayout layout = {});

// Writes new lights over the uploaded ones, as many as before (an OBJ model's rig placed
// for another camera): only the lights' range of the buffer is rewritten, and the kernel
// and the rest of the scene stay. Waits for the device to be idle first, and until done.
void updateGpuLights(const Context& context, GpuScene& scene,
                     const std::vector<gpu::GpuLight>& lights);

void destroyGpuScene(const Context& context, GpuScene& scene);
