#include "cli/version.h"

#include "gpu/shader_compiler.h"

#include <vulkan/vulkan_core.h>

std::string versionText() {
    const std::uint32_t vulkan = VK_HEADER_VERSION_COMPLETE;
    return std::string("Raytracer ") + RAYTRACER_VERSION + "\n" + "Vulkan headers " +
           std::to_string(VK_API_VERSION_MAJOR(vulkan)) + "." +
           std::to_string(VK_API_VERSION_MINOR(vulkan)) + "." +
           std::to_string(VK_API_VERSION_PATCH(vulkan)) + "\n" + "glslang " + glslangVersion() +
           "\n";
}
