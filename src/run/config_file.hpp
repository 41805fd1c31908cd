// Config files: TOML -> RunSettings. Unknown keys, wrong types and out-of-range values are
// errors naming file:line:column; `overrides` ("ga.population=50") are applied first.
// parseConfig also records, when given `keys`, every key the stages asked for with its type,
// default, range and meaning (the config reference is written from that).
#pragma once
#include <string>
#include <vector>

#include "run/config_key_record.hpp"
#include "run/settings.hpp"

namespace shapevo {

RunSettings loadConfig(const std::string& path, const std::vector<std::string>& overrides = {});
RunSettings parseConfig(const std::string& text, const std::string& path, const std::vector<std::string>& overrides = {},
                        std::vector<ConfigKeyRecord>* keys = nullptr);

}  // namespace shapevo
