// Text taken from a damaged file, safe to print in a message.
#pragma once

#include <string>
#include <string_view>

// text with every byte outside printable ASCII as \xNN.
std::string printableText(std::string_view text);
