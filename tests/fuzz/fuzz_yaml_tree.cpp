// libFuzzer target: arbitrary bytes -> graph::parseYaml with small limits. A located InputError
// ("fuzz.yml:LINE:COL: message", the place inside the text, one line) is the expected way to
// reject input; any other exception, a sanitizer report, a leak, or an accepted tree that breaks
// the limits or has a node placed outside the text is a crash. See CMakeLists.txt here for how to
// build and run it.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "base/input_error.hpp"
#include "graph/yaml_tree.hpp"

namespace fuzz_yaml_tree {

[[noreturn]] void broken(const char* what) {
    std::fprintf(stderr, "fuzz_yaml_tree: invariant broken: %s\n", what);
    std::abort();
}
#define YAML_FUZZ_CHECK(cond)          \
    do {                               \
        if (!(cond)) broken(#cond);    \
    } while (0)

// 1-based line and column (characters or bytes, never more than the line's bytes + 1) inside text.
bool inside(const std::string& text, int line, int column) {
    int l = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < text.size() && l < line; ++i)
        if (text[i] == '\n') {
            ++l;
            lineStart = i + 1;
        }
    if (line < 1 || l != line) return false;
    std::size_t lineEnd = text.find('\n', lineStart);
    if (lineEnd == std::string::npos) lineEnd = text.size();
    return column >= 1 && std::size_t(column) <= lineEnd - lineStart + 1;
}

void checkLocated(const shapevo::InputError& e, const std::string& text, const std::string& file) {
    const std::string what = e.what();
    const std::string prefix = file + ":";
    YAML_FUZZ_CHECK(e.file() == file && what.rfind(prefix, 0) == 0);
    YAML_FUZZ_CHECK(what.find('\n') == std::string::npos && !e.message().empty());
    int line = 0, column = 0, consumed = 0;
    YAML_FUZZ_CHECK(std::sscanf(what.c_str() + prefix.size(), "%d:%d: %n", &line, &column, &consumed) == 2 &&
                    consumed > 0);
    YAML_FUZZ_CHECK(inside(text, line, column));
}

// Walks the accepted tree with an explicit stack, counting nodes and depth.
void checkAccepted(const shapevo::graph::YamlNode& root, const std::string& text,
                   const shapevo::graph::YamlLimits& limits) {
    using shapevo::graph::YamlNode;
    std::vector<std::pair<const YamlNode*, int>> todo{{&root, 0}};
    std::size_t nodes = 0;
    while (!todo.empty()) {
        const auto [node, depth] = todo.back();
        todo.pop_back();
        ++nodes;
        YAML_FUZZ_CHECK(inside(text, node->line, node->column) || (text.empty() && node->line == 1));
        if (node->kind == YamlNode::Kind::Sequence) {
            YAML_FUZZ_CHECK(depth < limits.maxDepth);
            for (const YamlNode& item : node->items) todo.push_back({&item, depth + 1});
        } else if (node->kind == YamlNode::Kind::Mapping) {
            YAML_FUZZ_CHECK(depth < limits.maxDepth);
            for (const auto& [key, value] : node->entries) {
                YAML_FUZZ_CHECK(key.isScalar());
                todo.push_back({&key, depth + 1});
                todo.push_back({&value, depth + 1});
            }
        }
        (void)node->describe();
    }
    YAML_FUZZ_CHECK(nodes <= limits.maxNodes);
}

}  // namespace fuzz_yaml_tree

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    shapevo::graph::YamlLimits limits;
    limits.maxBytes = 1 << 16;
    limits.maxDepth = 16;
    limits.maxNodes = 5000;
    limits.maxAliasNodes = 2000;
    try {
        const shapevo::graph::YamlNode root = shapevo::graph::parseYaml(text, "fuzz.yml", limits);
        fuzz_yaml_tree::checkAccepted(root, text, limits);
    } catch (const shapevo::InputError& e) {
        if (size > limits.maxBytes) return 0;  // refused before parsing, with no place
        fuzz_yaml_tree::checkLocated(e, text, "fuzz.yml");
    }
    return 0;
}
