// The values of the command line's option texts (`run --seed`, `sample --seed/--count/--attr`,
// `translate --attr`) and the names of the files a command writes. Promises: a value is exact
// (never saturated or wrapped) or an InputError naming the option and what it expected; an
// output name is refused before anything is written if a file of that name exists.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "grammar/attr_overrides.hpp"

namespace shapevo {

/// The seed an option gives: a whole number in [0, max], exactly (never saturated or wrapped).
/// @throw InputError(option) otherwise.
std::uint64_t parseSeed(const std::string& text, const std::string& option, std::uint64_t max);

/// --count: a whole number in [1, max]. @throw InputError("--count") otherwise.
std::uint32_t parseCount(const std::string& text, std::uint32_t max);

/// --attr NAME=VALUE options as attr overrides. @throw InputError("--attr") for one that is not NAME=NUMBER.
AttrOverrides parseAttrOptions(const std::vector<std::string>& options);

/// The k-th (1-based) of `count` output names: `path` itself if count is 1, else `path` with
/// "-NNN" before its extension (out.obj -> out-001.obj; at least 3 digits, as many as count has).
std::string numberedPath(const std::string& path, std::uint32_t k, std::uint32_t count);

/// @throw InputError(path) if a file or folder `path` exists: shapevo does not overwrite files.
void refuseExisting(const std::string& path);

}  // namespace shapevo
