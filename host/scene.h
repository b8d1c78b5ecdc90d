// The scene as the file states it: text in, plain CPU structs out. No Vulkan here.
// Values are kept in double precision so that the CPU reference sees exactly the
// numbers in the file; the GPU packer rounds them to float.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

struct Material {
    glm::dvec3 diffuse{0.0};  // kd, "dif:"
    glm::dvec3 specular{0.0}; // ks, "spe:"; also the mirror weight of the reflection
    double shininess = 0.0;   // Phong exponent, "shi:"
};

struct Sphere {
    glm::dvec3 center{0.0};
    double radius = 0.0;
    Material material;
};

struct Vertex {
    glm::dvec3 position{0.0};
    glm::dvec3 normal{0.0}; // as given; may be unnormalised or zero
    Material material;
};

struct Triangle {
    Vertex vertices[3];
};

struct Light {
    glm::dvec3 position{0.0};
    glm::dvec3 color{0.0};
};

struct Scene {
    glm::dvec3 ambient{0.0};
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles;
    std::vector<Light> lights;
    // Accepted oddities ("file:line: warning: ..."), printed by the caller.
    std::vector<std::string> warnings;
};

// A scene file that does not follow the format. what() reads
// "FILE:LINE: error: MESSAGE", ready to print.
struct SceneError : std::runtime_error {
    SceneError(std::string file, int line, std::string message);
    std::string file;
    int line;            // 1-based; 0 when the error concerns the whole file
    std::string message; // what was expected, without the location
};

// Parses scene text. fileName is used in messages only.
Scene parseScene(std::string_view text, const std::string& fileName);

// How parseScene shares a large text among threads. The result, errors included, is
// the same for any setting; the defaults suit every caller, and the tests shrink the
// chunks to take the parallel path on small texts.
struct SceneParseOptions {
    unsigned threads = 0;                 // 0: one per hardware thread, at most 8
    std::size_t minChunkBytes = 1u << 20; // no thread gets less text than this
};
Scene parseScene(std::string_view text, const std::string& fileName,
                 const SceneParseOptions& options);

// Reads and parses a file; a missing, unreadable or binary file is a SceneError.
Scene loadScene(const std::filesystem::path& path);
