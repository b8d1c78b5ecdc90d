// The files a model file names (material libraries, textures, buffers): where they are.
#pragma once

#include <string>

// The folder of path ("" when it has none).
std::string directoryOf(const std::string& path);

// A file a model file names, as a path from where the model file is found: name itself when
// absolute or when the model file is in the current folder.
std::string besideFile(const std::string& modelFile, const std::string& name);

// The file a model names, as found: exporters on Windows write folders with backslashes and
// glTF's URIs escape characters (%20 for a space), neither of which names a file here as
// written; such a name is tried with slashes and unescaped when it names no file. Returns
// named itself when nothing is found.
std::string foundFile(const std::string& named);
