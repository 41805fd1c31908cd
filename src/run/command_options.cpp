// Option values and output names of the commands (command_options.hpp).
#include "run/command_options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "base/input_error.hpp"

namespace shapevo {

std::uint64_t parseSeed(const std::string& text, const std::string& option, std::uint64_t max) {
    const std::string range = "[0, " + std::to_string(max) + "]";
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ptr != end || (ec != std::errc() && ec != std::errc::result_out_of_range))
        throw InputError(option, "", "expected a whole number in " + range + ", got \"" + shortened(text) + "\"");
    if (ec == std::errc::result_out_of_range || v > max)
        throw InputError(option, "", shortened(text) + " is out of range " + range +
                                         (max < UINT64_MAX ? " (the largest seed a config's run.seed holds; the run's config.toml records it)" : ""));
    return v;
}

std::uint32_t parseCount(const std::string& text, std::uint32_t max) {
    std::uint32_t v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ptr != end || ec != std::errc() || v < 1 || v > max)
        throw InputError("--count", "", "expected a whole number of files from 1 to " + std::to_string(max) + ", got \"" +
                                            shortened(text) + "\"");
    return v;
}

AttrOverrides parseAttrOptions(const std::vector<std::string>& options) {
    AttrOverrides attrs;
    for (const std::string& a : options) {
        const auto eq = a.find('=');
        char* end = nullptr;
        const double v = eq == std::string::npos ? 0.0 : std::strtod(a.c_str() + eq + 1, &end);
        if (eq == std::string::npos || eq == 0 || end == a.c_str() + eq + 1 || *end != '\0' || !std::isfinite(v))
            throw InputError("--attr", a, "expected NAME=NUMBER, e.g. --attr taper=0.6");
        attrs[a.substr(0, eq)] = v;
    }
    return attrs;
}

std::string numberedPath(const std::string& path, std::uint32_t k, std::uint32_t count) {
    if (count == 1) return path;
    const std::filesystem::path p(path);
    std::string n = std::to_string(k);
    n.insert(0, std::max<std::size_t>(3, std::to_string(count).size()) - n.size(), '0');
    return (p.parent_path() / (p.stem().string() + "-" + n + p.extension().string())).string();
}

void refuseExisting(const std::string& path) {
    if (std::filesystem::exists(path))
        throw InputError(path, "", "already exists; shapevo does not overwrite files (remove it or choose another -o)");
}

}  // namespace shapevo
