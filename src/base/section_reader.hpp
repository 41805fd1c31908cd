// SectionReader: how a stage reads its own part of a config without knowing the file format.
// A stage that owns settings (a search method, for instance) writes a function taking a
// SectionReader and asks it for each key it knows; run/config_file.cpp implements it over TOML.
// Contract: a key that is absent leaves the value as it was (the default); a key that is present
// but of the wrong type or outside [lo, hi] throws InputError naming the file, line and key; every
// key asked for counts as known, so a key no reader asks for is reported as unknown.
#pragma once
#include <cstdint>
#include <string_view>

namespace shapevo {

class SectionReader {
public:
    virtual void number(std::string_view key, double& value, double lo, double hi) = 0;
    /// A whole number in [lo, hi].
    virtual void count(std::string_view key, std::uint32_t& value, double lo, double hi) = 0;
    virtual void flag(std::string_view key, bool& value) = 0;

protected:
    ~SectionReader() = default;
};

}  // namespace shapevo
