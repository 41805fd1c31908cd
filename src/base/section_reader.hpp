// SectionReader: how a stage reads its own part of a config without knowing the file format.
// A stage that owns settings (a search method, a target kind, the GA, migration, ...) writes a
// function taking a SectionReader (or a ConfigReader, for a stage with more than one section) and
// asks it for each key it knows; run/config_file.cpp implements both over TOML and only gathers
// what the stages read.
// Contract: a key that is absent leaves the value as it was (the default); a key that is present
// but of the wrong type or outside [lo, hi] throws InputError naming the file, line:column and
// key (or "--set" for a value given on the command line); every key asked for (has() too) counts
// as known, so a key no reader asks for is reported as unknown. Messages name keys as
// "section.key".
// Every read states the key's meaning in one or two sentences (`meaning`): the config reference
// (`shapevo reference config`, docs/reference/config.md) is made from these calls, with the
// value the variable held before the read as the key's default, so it cannot drift from the code.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace shapevo {

class SectionReader {
public:
    virtual void number(std::string_view key, double& value, double lo, double hi, std::string_view meaning) = 0;
    /// A whole number in [lo, hi].
    virtual void count(std::string_view key, std::uint32_t& value, double lo, double hi, std::string_view meaning) = 0;
    /// A whole number in [0, 2^63 - 1] (TOML's largest integer), read exactly (not through a double).
    virtual void wholeNumber64(std::string_view key, std::uint64_t& value, std::string_view meaning) = 0;
    /// true or false.
    virtual void flag(std::string_view key, bool& value, std::string_view meaning) = 0;
    virtual void string(std::string_view key, std::string& value, std::string_view meaning) = 0;
    /// A string or an array of strings (empty when the key is absent).
    virtual std::vector<std::string> strings(std::string_view key, std::string_view meaning) = 0;
    /// An array of exactly values.size() numbers; returns whether the key is present.
    virtual bool numbers(std::string_view key, std::span<double> values, std::string_view meaning) = 0;
    /// A table of finite numbers (NAME = 1.5, ...) into `values`, keyed by name; returns whether
    /// the key is present.
    virtual bool numberTable(std::string_view key, std::map<std::string, double>& values, std::string_view meaning) = 0;
    /// numbers() into a glm vector (dvec2, dvec3).
    template <class Vec>
    bool vec(std::string_view key, Vec& v, std::string_view meaning) {
        return numbers(key, std::span<double>(&v[0], std::size_t(Vec::length())), meaning);
    }
    /// Whether the key is in the section (it counts as known).
    virtual bool has(std::string_view key) = 0;
    /// Whether the section is in the config at all.
    virtual bool present() const = 0;

    /// The config file's path, for a stage's own check (see located()).
    virtual const std::string& file() const = 0;
    /// A file path as written in the config, resolved against the config file's folder
    /// (absolute paths are kept).
    virtual std::string resolvePath(const std::string& written) const = 0;

    /// @throw InputError at `key` (present) of this section, or naming --set if it came from there.
    [[noreturn]] virtual void fail(std::string_view key, const std::string& what) const = 0;
    /// A rule over several keys ("ga.elitism", "ga.population", any section) is broken: blame
    /// --set if one of them came from it, else the place of the last of them in the file, else
    /// `where` ("[ga]", or "" for the file alone).
    [[noreturn]] virtual void failKeys(const std::vector<std::string>& qualifiedKeys, const std::string& where,
                                       const std::string& what) const = 0;
    /// The section as a whole is wrong: blame --set if it came from there, else "[section]".
    [[noreturn]] virtual void failSection(const std::string& what) const = 0;
    /// Run `check`, a stage's own check that throws InputError(file(), "section.key", what): give
    /// its error the key's line:column, or blame --set if the key came from there.
    virtual void located(const std::function<void()>& check) const = 0;

protected:
    ~SectionReader() = default;
};

/// The sections of a config, for a stage that reads more than one (a target kind: [target] and
/// [camera]).
class ConfigReader {
public:
    /// The reader of [name], the same one on every call; opening it makes the section known.
    /// @throw InputError if [name] is in the config but not a table.
    virtual SectionReader& section(std::string_view name) = 0;

protected:
    ~ConfigReader() = default;
};

}  // namespace shapevo
