// How many triangles one device can hold, from its limits, so that a file too large for it
// is refused as soon as its count is known (an OBJ's survey, a binary header, the end of a
// scene text's parse), not after the long work of the model, the packing and the
// hierarchy. The count that decides is the triangles' largest array, the largest per triangle
// (shaders/shared.h): their corners (3 vec4 a triangle, 3 dvec4 in fp64), or indexed their
// vertex indices (a uvec4). The vertices' arrays are left out (their count is not known
// yet), so the check is one a scene must pass; what it lets through, the upload checks
// again array by array (render/scene_upload.h).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

// The limits that bound a scene's arrays (render/device_capacity.h reads them off a device).
struct SceneCapacity {
    std::string device; // its name, for messages
    std::uint64_t maxTexelBufferElements = 0;
    std::uint64_t maxStorageBufferRange = 0;
    std::uint64_t maxMemoryAllocationSize = 0; // 0: no limit known (one array per buffer)
    std::uint64_t alignment = 16;              // of an array in its buffer (scene_upload.cpp)
    bool texelReads = true;                    // the corners may be read through their texel view
    bool fp64 = false; // --precision fp64: corners of doubles, read as storage
    // The triangle layouts the scene may take (packing/triangle_layout.h, --triangle-layout):
    // the one that holds the more triangles counts.
    bool cornersAllowed = true;
    bool indexedAllowed = true;
};

// The most triangles the device holds, and the limit that sets it.
struct TriangleCapacity {
    std::uint64_t triangles = 0;
    // "maxTexelBufferElements of 134217728 (3 texels a triangle)"; indexed: "..., indexed)"
    std::string limit;
};
TriangleCapacity triangleCapacity(const SceneCapacity& capacity);

// A scene larger than the device holds: not a malformed file (SceneError), but one that a
// larger device would render.
struct CapacityError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws a CapacityError, naming the file, the device, the limit and the largest count that fits,
// when `triangles` are more than the device holds.
void checkTriangleCapacity(const SceneCapacity& capacity, std::uint64_t triangles,
                           const std::string& fileName);
