// ReaderContext: located errors, id table, scalar conversions and compilation for the reader.
#include "graph/reader_context.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "base/input_error.hpp"

namespace shapevo::graph::reading {

void ReaderContext::fail(const YamlNode& at, const std::string& message) const {
    throw InputError(path_, at.where(), message);
}

void ReaderContext::fail(const Place& at, const std::string& message) const {
    throw InputError(path_, at.node->where(), at.what.empty() ? message : at.what + ": " + message);
}

const YamlNode& ReaderContext::mapping(const YamlNode& n, const std::string& what) const {
    if (n.kind != YamlNode::Kind::Mapping) fail(n, what + " must be a mapping, not " + n.describe());
    return n;
}

const YamlNode& ReaderContext::sequence(const YamlNode& n, const std::string& what) const {
    if (n.kind != YamlNode::Kind::Sequence) fail(n, what + " must be a list, not " + n.describe());
    return n;
}

const YamlNode& ReaderContext::required(const YamlNode& map, std::string_view key, const std::string& what) const {
    const YamlNode* n = map.find(key);
    if (!n) fail(map, what + " has no '" + std::string(key) + "'");
    return *n;
}

void ReaderContext::onlyKeys(const YamlNode& map, std::initializer_list<std::string_view> allowed, const std::string& what) const {
    for (const auto& [key, value] : map.entries) {
        const std::string k = keyText(key, what);
        bool known = false;
        for (std::string_view a : allowed) known = known || a == k;
        if (known) continue;
        std::string list;
        for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        fail(key, what + ": unknown key '" + shortened(k) + "' (expected " + list + ")");
    }
}

std::string ReaderContext::keyText(const YamlNode& key, const std::string& what) const {
    if (!key.isScalar()) fail(key, what + ": a key must be a scalar, not " + key.describe());
    return key.text;
}

std::int64_t ReaderContext::integer(const YamlNode& n, const std::string& what) const {
    if (n.kind == YamlNode::Kind::Int) return n.integer;
    if (n.kind == YamlNode::Kind::String) {  // an id or count written as a string: '7'
        const char* begin = n.text.c_str();
        char* end = nullptr;
        errno = 0;
        const long long v = std::strtoll(begin, &end, 10);
        if (end != begin && *end == '\0' && errno == 0) return v;
    }
    fail(n, what + " must be a whole number, not " + n.describe());
}

std::int64_t ReaderContext::id(const YamlNode& n, const std::string& what) const {
    if (n.kind != YamlNode::Kind::Int) fail(n, what + " must be a whole number (an id), not " + n.describe());
    return n.integer;
}

double ReaderContext::number(const YamlNode& n, const std::string& what) const {
    switch (n.kind) {
        case YamlNode::Kind::Int: return double(n.integer);
        case YamlNode::Kind::Float: return n.number;
        case YamlNode::Kind::String: {
            std::string_view t = n.text;
            while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
            while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.remove_suffix(1);
            const std::string s(t);
            const bool hex = s.find_first_of("xX") != std::string::npos;  // Python's float() reads no hex
            char* end = nullptr;
            const double v = std::strtod(s.c_str(), &end);
            if (!s.empty() && !hex && end == s.c_str() + s.size()) return v;
            break;
        }
        default: break;
    }
    fail(n, what + " must be a number, not " + n.describe());
}

Value ReaderContext::plainValue(const YamlNode& n, const std::string& what) const {
    switch (n.kind) {
        case YamlNode::Kind::Null: return Value();
        case YamlNode::Kind::Bool: return Value(n.boolean);
        case YamlNode::Kind::Int: return Value(n.integer);
        case YamlNode::Kind::Float: return Value(n.number);
        case YamlNode::Kind::String: return Value(n.text);
        default: fail(n, what + " must be a single value, not " + n.describe());
    }
}

std::string ReaderContext::expressionText(const YamlNode& n, const std::string& what) const {
    switch (n.kind) {
        case YamlNode::Kind::Null: return "None";
        case YamlNode::Kind::Bool: return n.boolean ? "True" : "False";
        case YamlNode::Kind::Int: return std::to_string(n.integer);
        case YamlNode::Kind::Float: return toText(Value(n.number));
        case YamlNode::Kind::String: return n.text;
        default: fail(n, what + " must be an expression (a string), not " + n.describe());
    }
}

const YamlNode& ReaderContext::elementEntry(const YamlNode& entry, bool vertex, const std::string& graphWhat,
                                            std::string& elementWhat) {
    const std::string kind = vertex ? " vertex" : " edge";
    mapping(entry, graphWhat + kind);
    if (vertex) onlyKeys(entry, {"id", "attr"}, graphWhat + kind);
    else onlyKeys(entry, {"id", "vertex1", "vertex2", "attr"}, graphWhat + kind);
    const YamlNode& idNode = required(entry, "id", graphWhat + kind);
    elementWhat = graphWhat + "," + kind + " " + idText(idNode);
    declareId(idNode, elementWhat);
    return idNode;
}

void ReaderContext::declareId(const YamlNode& idNode, const std::string& what) {
    const std::int64_t id = this->id(idNode, what + "'s id");
    const auto [it, fresh] = ids_.emplace(id, std::make_pair(idNode.line, what));
    if (!fresh)
        fail(idNode, what + ": id " + std::to_string(id) + " is already the id of " + it->second.second + " (line " +
                         std::to_string(it->second.first) + "); ids must be unique in the whole file");
}

void ReaderContext::countScope(std::size_t names, const YamlNode& at, const std::string& what) {
    scopeNames_ += names;
    if (scopeNames_ > kMaxNamesInScopes)
        fail(at, what + ": the file's productions and options see more than " + std::to_string(kMaxNamesInScopes) +
                     " names in all (every option sees every global variable); use fewer global variables or options");
}

namespace {

bool continuesCharacter(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

/// Characters (UTF-8) in `s`.
std::size_t characters(std::string_view s) {
    std::size_t n = 0;
    for (char c : s) n += continuesCharacter(c) ? 0 : 1;
    return n;
}

}  // namespace

std::string ReaderContext::placeInside(const YamlNode& n, const std::string& text, std::size_t offset) const {
    if (source_.empty() || n.line < 1 || n.column < 1 || offset > text.size() || text.find('\n') != std::string::npos) return "";
    // The node's line, then its column (counted in characters), past an opening quote.
    std::size_t at = 0;
    for (int line = 1; line < n.line; ++line) {
        at = source_.find('\n', at);
        if (at == std::string_view::npos) return "";
        ++at;
    }
    for (int column = 1; column < n.column; ++column) {
        if (at >= source_.size() || source_[at] == '\n') return "";
        ++at;
        while (at < source_.size() && continuesCharacter(source_[at])) ++at;
    }
    int column = n.column;
    if (n.quoted) {
        if (at >= source_.size() || (source_[at] != '\'' && source_[at] != '"')) return "";  // a block scalar
        ++at, ++column;
    }
    const std::size_t lineEnd = std::min(source_.find('\n', at), source_.size());
    if (source_.substr(at, std::min(text.size(), lineEnd - at)) != text) return "";  // folded or escaped
    return std::to_string(n.line) + ":" + std::to_string(column + int(characters(std::string_view(text).substr(0, offset))));
}

CompiledExpression ReaderContext::compile(const YamlNode& n, const NameSlots& slots, const std::string& what) const {
    const std::string text = expressionText(n, what);
    try {
        return compileExpression(text, slots, names_);
    } catch (const ExpressionError& e) {
        // The column inside the expression where the source shows it as is; otherwise the
        // scalar's start, and the offset in its text.
        const std::string inside = placeInside(n, text, e.offset());
        std::string message = what + ": " + e.what();
        if (inside.empty()) message += " (at character " + std::to_string(characters(std::string_view(text).substr(0, e.offset())) + 1) + " of '" + shortened(text, 60) + "')";
        throw InputError(path_, inside.empty() ? n.where() : inside, message);
    }
}

std::string idText(const YamlNode& n) { return n.kind == YamlNode::Kind::Int ? std::to_string(n.integer) : shortened(n.text); }

bool truthyScalar(const YamlNode& n) {
    switch (n.kind) {
        case YamlNode::Kind::Null: return false;
        case YamlNode::Kind::Bool: return n.boolean;
        case YamlNode::Kind::Int: return n.integer != 0;
        case YamlNode::Kind::Float: return n.number != 0;
        case YamlNode::Kind::String: return !n.text.empty();
        case YamlNode::Kind::Sequence: return !n.items.empty();
        case YamlNode::Kind::Mapping: return !n.entries.empty();
    }
    return true;
}

bool isHelperVertex(const YamlNode& vertex) {
    const YamlNode* attrs = vertex.find("attr");
    if (!attrs || attrs->kind != YamlNode::Kind::Mapping) return false;
    const YamlNode* h = attrs->find(".helper_node");
    return h && truthyScalar(*h);
}

}  // namespace shapevo::graph::reading
