// Wavefront MTL material libraries, as an OBJ file's mtllib names them (docs/models.md):
// Kd, Ks, Ns, Ke, illum and map_Kd of each newmtl material. A wrong line is a warning, not
// an error: its material falls back to the default one and the model renders on.
#pragma once

#include "model/source_model.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>

// A material library, looked up by the name an mtllib line gives: the path it has in
// messages, and its text, or no text when there is no such file.
struct MtlFile {
    std::string path;
    std::optional<std::string> text;
};
using MtlLookup = std::function<MtlFile(const std::string& name)>;

// Appends file's materials to model.materials, each name to `names` (a later definition of
// a name wins), its warnings to model.warnings and what it does not render to
// model.notRendered. file.text must be set.
void readMtl(const MtlFile& file, SourceModel& model, std::map<std::string, std::uint32_t>& names);
