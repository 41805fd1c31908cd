// formatDouble: std::to_chars, shortest round-trip form.
#include "base/format_double.hpp"

#include <charconv>

namespace shapevo {

std::string formatDouble(double v) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, end);
}

}  // namespace shapevo
