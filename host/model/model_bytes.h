// A SourceModel as bytes and back, so that a model read in a child process
// (contained_reader.h) reaches the parent whole. Not a file format: both ends are the same
// build, and nothing is kept.
#pragma once

#include "model/source_model.h"

#include <string>
#include <string_view>

std::string modelBytes(const SourceModel& model);

// The model modelBytes wrote; throws std::runtime_error when the bytes are cut short or
// name positions, normals or materials that are not there.
SourceModel modelFromBytes(std::string_view bytes);
