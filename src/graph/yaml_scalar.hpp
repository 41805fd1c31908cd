// YAML scalar resolution as PyYAML 6's SafeLoader does it (yaml/resolver.py's implicit resolvers
// for YAML 1.1 and yaml/constructor.py's SafeConstructor), for yaml_tree.cpp. Plain scalars:
// bool (yes/no/true/false/on/off in three casings), null (~, null/Null/NULL, empty), int
// (decimal with '_', 0b binary, 0x hex, leading-0 octal, sexagesimal 190:20:30), float (a dot or a
// sexagesimal with a dot, an exponent only with a sign: '1e3' stays a string, .inf/.nan forms).
// Two differences, both refusals or strings where PyYAML would hand the original tool a value no
// grammar can use: a timestamp (2001-12-14) stays a string (PyYAML makes a date), and an integer
// beyond 64 bits is an error (Python's ints are unbounded). Pure functions; no allocation beyond
// the node's own text.
#pragma once
#include <string>
#include <string_view>

#include "graph/yaml_tree.hpp"

namespace shapevo::graph::yaml_scalar {

/// Sets node.kind and its value from node.text. `tag` is libyaml's resolved tag ("" for none,
/// "!" for the non-specific tag, "tag:yaml.org,2002:int", ...); `plain` is the scalar's style.
/// Returns "" on success, else a short message (an unsupported tag, "!!int abc", an integer
/// beyond 64 bits, a plain '=' or '<<' that PyYAML's safe loader refuses as well).
std::string resolve(YamlNode& node, std::string_view tag, bool plain);

/// The end of the message for a tag outside the safe set.
inline constexpr std::string_view kRefusedTag =
    " is refused: a safe loader reads only !!str, !!int, !!float, !!bool, !!null, !!seq and !!map";

/// The tag as a user writes it: "tag:yaml.org,2002:python/object" -> "!!python/object".
std::string shortTag(std::string_view tag);

}  // namespace shapevo::graph::yaml_scalar
