// YamlTree: libyaml's event API turned into a YamlNode tree with an explicit stack (no recursion,
// so 100,000 nested '[' fail on the depth limit, not the C++ stack). Promises (yaml_tree.hpp):
// every node located, every limit checked before the work it bounds (an alias's size before it is
// copied), every failure an InputError naming the file, line and column.
//
// Choices, where PyYAML would do otherwise (each an error rather than a silent reading):
// - a duplicate key in one mapping is an error naming both places (PyYAML keeps the last value
//   silently; keys compare as Python's dict does, so 1, 1.0 and true are the same key);
// - merge keys ('<<') are refused with a message (PyYAML merges; the original tool's files, written
//   by yaml.dump, never hold them);
// - an alias inside its own anchor's node is refused (PyYAML builds a recursive list);
// - a second document is an error, as in PyYAML's safe_load;
// - the file must be UTF-8 (a BOM is allowed), as the original read it (Python's open()).
#include "graph/yaml_tree.hpp"

#include <yaml.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <unordered_map>
#include <unordered_set>

#include "base/input_error.hpp"
#include "graph/yaml_scalar.hpp"

namespace shapevo::graph {
namespace {

// Character index (libyaml's marks count characters; line breaks include NEL, LS, PS and lone CR)
// or byte offset -> 1-based line and column as an editor shows them: lines end at '\n' only,
// columns count characters. Walks forward from the last answer, so a document costs one pass.
class Locator {
public:
    explicit Locator(std::string_view text) : text_(text) {}

    struct Place {
        int line = 1, column = 1;
        std::string text() const { return std::to_string(line) + ":" + std::to_string(column); }
    };

    Place atCharacter(std::size_t index) {
        if (index < chars_) reset();
        while (byte_ < text_.size() && chars_ < index) step();
        return place();
    }
    Place atByte(std::size_t offset) {
        if (offset < byte_) reset();
        while (byte_ < text_.size() && byte_ < offset) step();
        return place();
    }

private:
    void reset() { byte_ = chars_ = 0, line_ = column_ = 1; }
    void step() {
        const char c = text_[byte_++];
        ++chars_;
        while (byte_ < text_.size() && (static_cast<unsigned char>(text_[byte_]) & 0xC0) == 0x80) ++byte_;
        if (c == '\n') {
            ++line_;
            column_ = 1;
        } else
            ++column_;
    }
    Place place() const { return {line_, column_}; }

    std::string_view text_;
    std::size_t byte_ = 0, chars_ = 0;
    int line_ = 1, column_ = 1;
};

// A key as Python's dict compares it: null; bool, int and integral float as one number; other
// floats by value; strings by text. NaN has no identity (it is never a duplicate): "".
std::string keyIdentity(const YamlNode& key) {
    using K = YamlNode::Kind;
    switch (key.kind) {
    case K::Null: return "~";
    case K::Bool: return key.boolean ? "n1" : "n0";
    case K::Int: return "n" + std::to_string(key.integer);
    case K::Float:
        if (std::isnan(key.number)) return {};
        if (std::trunc(key.number) == key.number && std::fabs(key.number) < 9.2e18)
            return "n" + std::to_string(static_cast<std::int64_t>(key.number));
        {
            char buffer[40];
            std::snprintf(buffer, sizeof buffer, "f%a", key.number);
            return buffer;
        }
    default: return "s" + key.text;
    }
}

struct Frame {
    YamlNode node;                 // the Sequence or Mapping being filled
    std::string anchor;            // "" if none
    std::size_t nodesBefore = 0;   // the node count before this collection (its size at the end)
    int height = 1;                // 1 + the tallest child so far
    bool haveKey = false;          // a Mapping's key waits for its value
    YamlNode key;
    std::unordered_map<std::string, std::string> keys;  // identity -> where (duplicates)
};

struct Anchored {
    YamlNode node;
    std::size_t nodes = 0;  // in the subtree, aliases inside it expanded
    int height = 0;         // 0 for a scalar
};

class Builder {
public:
    using Place = Locator::Place;

    Builder(std::string_view text, const std::string& path, const YamlLimits& limits)
        : text_(text), path_(path), limits_(limits), locator_(text) {}

    YamlNode run() {
        yaml_parser_t parser;
        if (!yaml_parser_initialize(&parser)) throw InputError(path_, "", "out of memory starting the YAML parser");
        struct Guard {
            yaml_parser_t* p;
            ~Guard() { yaml_parser_delete(p); }
        } guard{&parser};
        yaml_parser_set_input_string(&parser, reinterpret_cast<const unsigned char*>(text_.data()), text_.size());
        yaml_parser_set_encoding(&parser, YAML_UTF8_ENCODING);
        for (;;) {
            yaml_event_t event;
            if (!yaml_parser_parse(&parser, &event)) failSyntax(parser);
            struct EventGuard {
                yaml_event_t* e;
                ~EventGuard() { yaml_event_delete(e); }
            } eventGuard{&event};
            if (event.type == YAML_STREAM_END_EVENT) break;
            handle(event);
        }
        if (!haveRoot_) {  // an empty stream: PyYAML's safe_load gives None
            root_.kind = YamlNode::Kind::Null;
            root_.line = root_.column = 1;
        }
        return std::move(root_);
    }

private:
    [[noreturn]] void fail(const Place& where, const std::string& what) const {
        throw InputError(path_, where.text(), what);
    }
    Place at(const yaml_mark_t& mark) { return locator_.atCharacter(mark.index); }

    [[noreturn]] void failSyntax(const yaml_parser_t& parser) {
        const std::string problem = parser.problem ? parser.problem : "unknown problem";
        switch (parser.error) {
        case YAML_MEMORY_ERROR: throw InputError(path_, "", "out of memory while parsing YAML");
        case YAML_READER_ERROR: {  // its offset counts bytes
            std::string what = "not UTF-8 text: " + problem;
            if (parser.problem_value >= 0) {
                char code[32];
                std::snprintf(code, sizeof code, " (#x%X)", static_cast<unsigned>(parser.problem_value));
                what += code;
            }
            fail(locator_.atByte(parser.problem_offset), what);
        }
        default: {
            std::string what = "YAML syntax: " + problem;
            if (parser.context) what += " (" + std::string(parser.context) + " at " + at(parser.context_mark).text() + ")";
            fail(at(parser.problem_mark), what);
        }
        }
    }

    void handle(const yaml_event_t& event) {
        switch (event.type) {
        case YAML_DOCUMENT_START_EVENT:
            if (++documents_ > 1) fail(at(event.start_mark), "one YAML document expected, found a second one");
            break;
        case YAML_SCALAR_EVENT: scalar(event); break;
        case YAML_ALIAS_EVENT: alias(event); break;
        case YAML_SEQUENCE_START_EVENT:
            open(event, YamlNode::Kind::Sequence, event.data.sequence_start.anchor, event.data.sequence_start.tag);
            break;
        case YAML_MAPPING_START_EVENT:
            open(event, YamlNode::Kind::Mapping, event.data.mapping_start.anchor, event.data.mapping_start.tag);
            break;
        case YAML_SEQUENCE_END_EVENT:
        case YAML_MAPPING_END_EVENT: close(); break;
        default: break;  // stream start, document end
        }
    }

    void countNodes(std::size_t n, const Place& where) {
        nodes_ += n;
        if (nodes_ + keptForAliases_ > limits_.maxNodes)
            fail(where, "more than " + std::to_string(limits_.maxNodes) +
                            " YAML nodes (aliases expanded): the file is too large or an alias bomb");
    }

    void checkAnchor(const unsigned char* anchor, const Place& where) {
        if (!anchor) return;
        const std::string name(reinterpret_cast<const char*>(anchor));
        if (anchors_.count(name) || openAnchors_.count(name))
            fail(where, "the anchor &" + shortened(name) + " is defined twice");
    }

    void scalar(const yaml_event_t& event) {
        const auto& s = event.data.scalar;
        YamlNode node;
        const Place where = at(event.start_mark);
        countNodes(1, where);
        checkAnchor(s.anchor, where);
        node.text.assign(reinterpret_cast<const char*>(s.value), s.length);
        node.quoted = s.style != YAML_PLAIN_SCALAR_STYLE;
        locate(node, where);
        const std::string error = yaml_scalar::resolve(node, s.tag ? reinterpret_cast<const char*>(s.tag) : "",
                                                       s.style == YAML_PLAIN_SCALAR_STYLE);
        if (!error.empty()) fail(where, error);
        if (s.anchor) {
            keep(reinterpret_cast<const char*>(s.anchor), node, 1, 0, where);
        }
        add(std::move(node), 0, where);
    }

    void alias(const yaml_event_t& event) {
        const Place where = at(event.start_mark);
        const std::string name(reinterpret_cast<const char*>(event.data.alias.anchor));
        const auto found = anchors_.find(name);
        if (found == anchors_.end()) {
            if (openAnchors_.count(name)) fail(where, "the alias *" + shortened(name) + " is inside its own anchor's node");
            fail(where, "the alias *" + shortened(name) + " names no anchor before it");
        }
        const Anchored& a = found->second;
        if (static_cast<int>(stack_.size()) + a.height > limits_.maxDepth)
            fail(where, "the alias *" + shortened(name) + " nests collections deeper than " +
                            std::to_string(limits_.maxDepth) + " levels");
        aliasNodes_ += a.nodes;
        if (aliasNodes_ > limits_.maxAliasNodes)
            fail(where, "aliases expand to more than " + std::to_string(limits_.maxAliasNodes) +
                            " YAML nodes in all: an alias bomb?");
        countNodes(a.nodes, where);  // before copying
        YamlNode copy = a.node;
        locate(copy, where);
        add(std::move(copy), a.height, where);
    }

    void open(const yaml_event_t& event, YamlNode::Kind kind, const unsigned char* anchor, const unsigned char* tag) {
        const Place where = at(event.start_mark);
        if (static_cast<int>(stack_.size()) >= limits_.maxDepth)
            fail(where, "collections nested deeper than " + std::to_string(limits_.maxDepth) + " levels");
        const std::string tagText = tag ? reinterpret_cast<const char*>(tag) : "";
        const std::string expected = kind == YamlNode::Kind::Sequence ? "tag:yaml.org,2002:seq" : "tag:yaml.org,2002:map";
        if (!tagText.empty() && tagText != "!" && tagText != expected) {
            const bool core = tagText == "tag:yaml.org,2002:seq" || tagText == "tag:yaml.org,2002:map" ||
                              tagText == "tag:yaml.org,2002:str" || tagText == "tag:yaml.org,2002:int" ||
                              tagText == "tag:yaml.org,2002:float" || tagText == "tag:yaml.org,2002:bool" ||
                              tagText == "tag:yaml.org,2002:null";
            fail(where, "the tag " + yaml_scalar::shortTag(tagText) +
                            (core ? std::string(" does not fit a ") +
                                        (kind == YamlNode::Kind::Sequence ? "sequence" : "mapping")
                                  : std::string(yaml_scalar::kRefusedTag)));
        }
        checkAnchor(anchor, where);
        Frame frame;
        frame.nodesBefore = nodes_;
        countNodes(1, where);
        frame.node.kind = kind;
        locate(frame.node, where);
        if (anchor) {
            frame.anchor = reinterpret_cast<const char*>(anchor);
            openAnchors_.insert(frame.anchor);
        }
        stack_.push_back(std::move(frame));
    }

    void close() {
        Frame frame = std::move(stack_.back());
        stack_.pop_back();
        const Place where{frame.node.line, frame.node.column};
        if (!frame.anchor.empty()) {
            openAnchors_.erase(frame.anchor);
            keep(frame.anchor, frame.node, nodes_ - frame.nodesBefore, frame.height, where);
        }
        add(std::move(frame.node), frame.height, where);
    }

    // Keeps a copy of an anchored node for its aliases (counted against maxNodes too).
    void keep(const std::string& name, const YamlNode& node, std::size_t nodes, int height, const Place& where) {
        keptForAliases_ += nodes;
        countNodes(0, where);
        anchors_.emplace(name, Anchored{node, nodes, height});
    }

    static void locate(YamlNode& node, const Place& where) {
        node.line = where.line;
        node.column = where.column;
    }

    // A finished node goes into the collection being filled, or is the document.
    void add(YamlNode&& node, int height, const Place& where) {
        if (stack_.empty()) {
            root_ = std::move(node);
            haveRoot_ = true;
            return;
        }
        Frame& top = stack_.back();
        top.height = std::max(top.height, height + 1);
        if (top.node.kind == YamlNode::Kind::Sequence) {
            top.node.items.push_back(std::move(node));
            return;
        }
        if (top.haveKey) {
            top.node.entries.emplace_back(std::move(top.key), std::move(node));
            top.haveKey = false;
            return;
        }
        if (!node.isScalar()) fail(where, "a mapping key must be a scalar, not " + node.describe());
        std::string identity = keyIdentity(node);
        if (!identity.empty()) {
            const auto [it, inserted] = top.keys.emplace(std::move(identity), where.text());
            if (!inserted)
                fail(where, "the key '" + shortened(node.text) + "' is repeated in this mapping (first at " +
                                it->second + ")");
        }
        top.key = std::move(node);
        top.haveKey = true;
    }

    std::string_view text_;
    const std::string& path_;
    const YamlLimits& limits_;
    Locator locator_;
    std::vector<Frame> stack_;
    std::unordered_map<std::string, Anchored> anchors_;
    std::unordered_set<std::string> openAnchors_;
    std::size_t nodes_ = 0, keptForAliases_ = 0, aliasNodes_ = 0;
    int documents_ = 0;
    YamlNode root_;
    bool haveRoot_ = false;
};

std::string megabytes(std::uintmax_t bytes) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f MB", static_cast<double>(bytes) / (1 << 20));
    return buffer;
}

}  // namespace

YamlNode::YamlNode() = default;
YamlNode::YamlNode(const YamlNode&) = default;
YamlNode::YamlNode(YamlNode&&) noexcept = default;
YamlNode& YamlNode::operator=(const YamlNode&) = default;
YamlNode& YamlNode::operator=(YamlNode&&) noexcept = default;
YamlNode::~YamlNode() = default;

const YamlNode* YamlNode::find(std::string_view key) const {
    if (kind != Kind::Mapping) return nullptr;
    for (const auto& [k, v] : entries)
        if (k.isScalar() && k.text == key) return &v;
    return nullptr;
}

std::string YamlNode::describe() const {
    switch (kind) {
    case Kind::Null: return "null";
    case Kind::Bool: return boolean ? "the boolean true" : "the boolean false";
    case Kind::Int: return "the integer " + shortened(text);
    case Kind::Float: return "the number " + shortened(text);
    case Kind::String: return "the string '" + shortened(text) + "'";
    case Kind::Sequence: return "a sequence";
    case Kind::Mapping: return "a mapping";
    }
    return "a node";
}

YamlNode parseYaml(std::string_view text, const std::string& path, const YamlLimits& limits) {
    if (text.size() > limits.maxBytes)
        throw InputError(path, "", "the file is " + megabytes(text.size()) + ", more than the limit of " +
                                       megabytes(limits.maxBytes));
    return Builder(text, path, limits).run();
}

YamlNode readYamlFile(const std::string& path, const YamlLimits& limits) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(path, "", "cannot read the file: " + ec.message());
    if (size > limits.maxBytes)
        throw InputError(path, "", "the file is " + megabytes(size) + ", more than the limit of " + megabytes(limits.maxBytes));
    std::ifstream in(path, std::ios::binary);
    std::string text(static_cast<std::size_t>(size), '\0');
    if (!in || !in.read(text.data(), static_cast<std::streamsize>(size)))
        throw InputError(path, "", "cannot read the file");
    return parseYaml(text, path, limits);
}

}  // namespace shapevo::graph
