// ConfigKeyRecord: one config key as the code that reads it states it — its section, name, type,
// default (the value before the read), range and meaning. parseConfig fills a list of them when
// asked (run/config_file.hpp); the config reference (run/config_reference.hpp) is written from it.
#pragma once
#include <string>

namespace shapevo {

struct ConfigKeyRecord {
    std::string section;       ///< "ga"
    std::string key;           ///< "population"
    std::string type;          ///< "whole number", "number", "true or false", "string", ...
    std::string defaultValue;  ///< as TOML would write it: 200, "hybrid", [0, 0, 10]; "" for none
    std::string range;         ///< "[2, 10000000]" for numbers, "" otherwise
    std::string meaning;
};

}  // namespace shapevo
