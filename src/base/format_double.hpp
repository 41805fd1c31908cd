// formatDouble: how every report, message and summary writes a double: the shortest text that
// reads back to the same value (std::to_chars), so outputs are exact and repeatable.
#pragma once
#include <string>

namespace shapevo {

std::string formatDouble(double v);

}  // namespace shapevo
