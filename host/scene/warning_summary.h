// The scene's warnings as printed: the first few of each kind, then one line per kind for
// the rest, so that a mesh with 35,000 zero normals does not bury everything else.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

// The kind of a "file:line: warning: message": the message with every number written N
// ("the triangle's vertex N normal has zero length").
std::string warningKind(const std::string& warning);

// warnings in their order, keeping the first perKind of each kind; then, for each kind
// with more (in the order the kinds first appear), one line
// "file: warning: ... and 34,985 more warnings that the triangle's vertex N normal has zero
// length", the file being that of the kind's first warning.
std::vector<std::string> summarisedWarnings(const std::vector<std::string>& warnings,
                                            std::size_t perKind = 20);
