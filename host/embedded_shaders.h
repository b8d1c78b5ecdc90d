// The shader sources compiled into the binary (generated from shaders/ at build time).
#pragma once

#include <map>
#include <string>
#include <string_view>

// File name (e.g. "trace.comp", "shared.h") to its text.
const std::map<std::string, std::string_view>& embeddedShaderSources();
