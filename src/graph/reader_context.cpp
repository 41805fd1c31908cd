// ReaderContext: located errors, id table, scalar conversions and compilation for the reader.
#include "graph/reader_context.hpp"

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

void ReaderContext::declareId(const YamlNode& idNode, const std::string& what) {
    const std::int64_t id = integer(idNode, what + "'s id");
    const auto [it, fresh] = ids_.emplace(id, std::make_pair(idNode.line, what));
    if (!fresh)
        fail(idNode, what + ": id " + std::to_string(id) + " is already the id of " + it->second.second + " (line " +
                         std::to_string(it->second.first) + "); ids must be unique in the whole file");
}

CompiledExpression ReaderContext::compile(const YamlNode& n, const NameSlots& slots, const std::string& what) const {
    const std::string text = expressionText(n, what);
    try {
        return compileExpression(text, slots, names_);
    } catch (const ExpressionError& e) {
        // The column inside a one-line scalar; a folded or quoted scalar: the offset in its text.
        const bool sameLine = !n.quoted && text.find('\n') == std::string::npos && n.text == text;
        const std::string where =
            sameLine ? std::to_string(n.line) + ":" + std::to_string(n.column + int(e.offset()))
                     : n.where();
        std::string message = what + ": " + e.what();
        if (!sameLine) message += " (at character " + std::to_string(e.offset() + 1) + " of '" + shortened(text, 60) + "')";
        throw InputError(path_, where, message);
    }
}

}  // namespace shapevo::graph::reading
