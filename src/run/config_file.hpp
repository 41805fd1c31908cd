// Config files: TOML -> RunSettings. Unknown keys, wrong types and out-of-range values are
// errors naming file:line:column; `overrides` ("ga.population=50") are applied first.
#pragma once
#include <string>
#include <vector>

#include "run/settings.hpp"

namespace shapevo {

RunSettings loadConfig(const std::string& path, const std::vector<std::string>& overrides = {});
RunSettings parseConfig(const std::string& text, const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace shapevo
