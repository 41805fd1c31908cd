// YamlTree: a YAML 1.1 document read with libyaml (the parser PyYAML, and so the original tool,
// uses) into a small tree whose every node knows its line and column. Scalars are resolved as
// PyYAML's SafeLoader resolves plain scalars (true/false/yes/no/on/off, null/~/empty, ints incl.
// 0x/0b/leading-0 octal/sexagesimal/decimal with _, floats incl. .inf/.nan; see yaml_scalar.hpp);
// quoted and block scalars are strings unless an explicit tag (!!int ...) says otherwise.
// Bounded whatever the input: file size, nesting depth and the number of nodes after aliases are
// expanded (a "billion laughs" alias bomb is an error, not a hang); a duplicate mapping key, a
// merge key '<<', a tag outside the safe set and a second document are errors (yaml_tree.cpp says
// where this differs from PyYAML). Errors are InputError naming the file, line and column (lines
// end at '\n', columns count characters, both from 1).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace shapevo::graph {

struct YamlLimits {
    std::size_t maxBytes = 16u << 20;     // the file's size
    int maxDepth = 64;                    // nested collections
    std::size_t maxNodes = 2'000'000;     // nodes, counting each alias's expansion and each anchored
                                          // node's copy kept for its aliases
    std::size_t maxAliasNodes = 100'000;  // nodes copied by all aliases together: an alias bomb stops
                                          // after this much work (a few MB), not at maxNodes
};

struct YamlNode {
    enum class Kind : std::uint8_t { Null, Bool, Int, Float, String, Sequence, Mapping };
    Kind kind = Kind::Null;
    bool boolean = false;
    std::int64_t integer = 0;     // Kind::Int (a plain int beyond 64 bits is an error)
    double number = 0;            // Kind::Float
    std::string text;             // the scalar as written (every scalar kind), for messages and strings
    bool quoted = false;          // written quoted or as a block (a string unless explicitly tagged)
    int line = 0, column = 0;     // 1-based, where the node starts (a copy made for an alias: its
                                  // root is placed at the alias, its children where the anchor's are)
    std::vector<YamlNode> items;                          // Kind::Sequence
    std::vector<std::pair<YamlNode, YamlNode>> entries;   // Kind::Mapping, in file order

    // Declared here, defaulted in yaml_tree.cpp: with clang and libstdc++, implicit (inline)
    // members would instantiate std::pair<YamlNode, YamlNode> while YamlNode is incomplete.
    YamlNode();
    YamlNode(const YamlNode&);
    YamlNode(YamlNode&&) noexcept;
    YamlNode& operator=(const YamlNode&);
    YamlNode& operator=(YamlNode&&) noexcept;
    ~YamlNode();

    bool isScalar() const { return kind != Kind::Sequence && kind != Kind::Mapping; }
    /// The value of `key` in a mapping whose keys are scalars, or nullptr.
    const YamlNode* find(std::string_view key) const;
    /// "line:column".
    std::string where() const { return std::to_string(line) + ":" + std::to_string(column); }
    /// "a mapping", "a string", "the integer 5", ... for messages.
    std::string describe() const;
};

/// Parses `text` (the contents of `path`, named in errors). One document; an empty file is Null.
YamlNode parseYaml(std::string_view text, const std::string& path, const YamlLimits& limits = {});
/// Reads and parses the file (InputError if it cannot be read or exceeds limits.maxBytes).
YamlNode readYamlFile(const std::string& path, const YamlLimits& limits = {});

}  // namespace shapevo::graph
