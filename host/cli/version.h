// --version's text: what was built, and from which Vulkan headers and glslang. No Vulkan
// call, so it answers on a machine without a driver.
#pragma once

#include <string>

// "Raytracer 0.9.0\nVulkan headers 1.3.239\nglslang 12.0.0\n".
std::string versionText();
