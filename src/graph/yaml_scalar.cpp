// PyYAML SafeLoader scalar resolution (see yaml_scalar.hpp). The regular expressions of PyYAML 6's
// resolver.py are matched by hand (no std::regex: a 16 MB file holds millions of scalars), and the
// values are built as constructor.py builds them: '_' removed, a sign, then 0b / 0x / leading-0
// octal / sexagesimal / decimal.
#include "graph/yaml_scalar.hpp"

#include "base/input_error.hpp"

#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <locale.h>

namespace shapevo::graph::yaml_scalar {
namespace {

constexpr std::string_view kYamlTagPrefix = "tag:yaml.org,2002:";

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isHex(char c) { return isDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

// The chars of `s` from `i` while `pred` holds; returns the new position.
template <class Pred>
std::size_t skipWhile(std::string_view s, std::size_t i, Pred pred) {
    while (i < s.size() && pred(s[i])) ++i;
    return i;
}

bool isBoolWord(std::string_view s, bool& value) {
    static constexpr std::string_view kTrue[] = {"yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON"};
    static constexpr std::string_view kFalse[] = {"no", "No", "NO", "false", "False", "FALSE", "off", "Off", "OFF"};
    for (std::string_view w : kTrue)
        if (s == w) return value = true;
    for (std::string_view w : kFalse)
        if (s == w) {
            value = false;
            return true;
        }
    return false;
}

bool isNullWord(std::string_view s) { return s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL"; }

// (?::[0-5]?[0-9])+ from `i`; returns the position after it, or npos if there is none. Greedy is
// exact here: a segment can only be followed by ':', '.' or the end, never by a digit.
std::size_t skipSexagesimal(std::string_view s, std::size_t i) {
    std::size_t segments = 0;
    while (i + 1 < s.size() && s[i] == ':' && isDigit(s[i + 1])) {
        i += 2;
        if (i < s.size() && isDigit(s[i]) && s[i - 1] <= '5') ++i;
        ++segments;
    }
    return segments ? i : std::string_view::npos;
}

std::size_t skipSign(std::string_view s) { return !s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0; }

// ^(?:[-+]?0b[0-1_]+|[-+]?0[0-7_]+|[-+]?(?:0|[1-9][0-9_]*)|[-+]?0x[0-9a-fA-F_]+
//    |[-+]?[1-9][0-9_]*(?::[0-5]?[0-9])+)$
bool matchesInt(std::string_view s) {
    const std::size_t i = skipSign(s);
    const std::string_view r = s.substr(i);
    if (r.empty()) return false;
    if (r.size() > 2 && r[0] == '0' && r[1] == 'b')
        return skipWhile(r, 2, [](char c) { return c == '0' || c == '1' || c == '_'; }) == r.size();
    if (r.size() > 2 && r[0] == '0' && r[1] == 'x')
        return skipWhile(r, 2, [](char c) { return isHex(c) || c == '_'; }) == r.size();
    if (r[0] == '0') return skipWhile(r, 1, [](char c) { return (c >= '0' && c <= '7') || c == '_'; }) == r.size();
    if (r[0] < '1' || r[0] > '9') return false;
    const std::size_t j = skipWhile(r, 1, [](char c) { return isDigit(c) || c == '_'; });
    return j == r.size() || skipSexagesimal(r, j) == r.size();
}

// (?:[eE][-+][0-9]+)? then the end.
bool exponentToEnd(std::string_view s, std::size_t i) {
    if (i == s.size()) return true;
    if ((s[i] != 'e' && s[i] != 'E') || i + 2 >= s.size() || (s[i + 1] != '-' && s[i + 1] != '+')) return false;
    return skipWhile(s, i + 2, isDigit) == s.size();
}

// ^(?:[-+]?(?:[0-9][0-9_]*)\.[0-9_]*(?:[eE][-+][0-9]+)?|\.[0-9][0-9_]*(?:[eE][-+][0-9]+)?
//    |[-+]?[0-9][0-9_]*(?::[0-5]?[0-9])+\.[0-9_]*|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$
bool matchesFloat(std::string_view s) {
    if (s == ".nan" || s == ".NaN" || s == ".NAN") return true;
    const std::size_t sign = skipSign(s);
    const std::string_view r = s.substr(sign);
    if (r == ".inf" || r == ".Inf" || r == ".INF") return true;
    auto digitOrUnderscore = [](char c) { return isDigit(c) || c == '_'; };
    if (r.size() >= 2 && r[0] == '.' && isDigit(r[1]))  // \.[0-9][0-9_]*: no sign allowed ('-.5' is a string)
        return sign == 0 && exponentToEnd(r, skipWhile(r, 2, digitOrUnderscore));
    if (r.empty() || !isDigit(r[0])) return false;
    std::size_t i = skipWhile(r, 1, digitOrUnderscore);
    if (i < r.size() && r[i] == '.') return exponentToEnd(r, skipWhile(r, i + 1, digitOrUnderscore));
    i = skipSexagesimal(r, i);
    if (i == std::string_view::npos || i >= r.size() || r[i] != '.') return false;
    return skipWhile(r, i + 1, digitOrUnderscore) == r.size();
}

std::string withoutUnderscores(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (char c : s)
        if (c != '_') out += c;
    return out;
}

// Digits of `s` in `base` into `out`: kOk, kInvalid (empty or not all digits) or kTooLarge.
enum class Parsed { kOk, kInvalid, kTooLarge };
Parsed parseUnsigned(std::string_view s, int base, std::uint64_t& out) {
    if (s.empty()) return Parsed::kInvalid;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out, base);
    if (end != s.data() + s.size()) return Parsed::kInvalid;
    if (ec == std::errc::result_out_of_range) return Parsed::kTooLarge;
    return ec == std::errc() ? Parsed::kOk : Parsed::kInvalid;
}

// constructor.py construct_yaml_int. Returns "" or what is wrong.
std::string constructInt(std::string_view text, std::int64_t& out) {
    std::string v = withoutUnderscores(text);
    bool negative = false;
    if (!v.empty() && (v[0] == '-' || v[0] == '+')) {
        negative = v[0] == '-';
        v.erase(0, 1);
    }
    std::uint64_t magnitude = 0;
    Parsed parsed = Parsed::kOk;
    if (v == "0")
        parsed = Parsed::kOk;
    else if (v.rfind("0b", 0) == 0)
        parsed = parseUnsigned(std::string_view(v).substr(2), 2, magnitude);
    else if (v.rfind("0x", 0) == 0)
        parsed = parseUnsigned(std::string_view(v).substr(2), 16, magnitude);
    else if (!v.empty() && v[0] == '0')
        parsed = parseUnsigned(std::string_view(v).substr(1), 8, magnitude);
    else if (v.find(':') != std::string::npos) {  // sexagesimal: 190:20:30 = 190*3600 + 20*60 + 30
        std::size_t start = 0;
        while (parsed == Parsed::kOk) {
            const std::size_t colon = v.find(':', start);
            std::uint64_t part = 0;
            parsed = parseUnsigned(std::string_view(v).substr(start, colon - start), 10, part);
            if (parsed == Parsed::kOk && (__builtin_mul_overflow(magnitude, 60u, &magnitude) ||
                                          __builtin_add_overflow(magnitude, part, &magnitude)))
                parsed = Parsed::kTooLarge;
            if (colon == std::string::npos) break;
            start = colon + 1;
        }
    } else
        parsed = parseUnsigned(v, 10, magnitude);
    if (parsed == Parsed::kInvalid) return "'" + shortened(text) + "' is not an integer";
    constexpr std::uint64_t kMaxPositive = std::numeric_limits<std::int64_t>::max();
    if (parsed == Parsed::kTooLarge || magnitude > kMaxPositive + (negative ? 1 : 0))
        return "the integer " + shortened(text) + " does not fit in 64 bits";
    out = negative ? static_cast<std::int64_t>(0 - magnitude) : static_cast<std::int64_t>(magnitude);
    return {};
}

// Python's float(s) for a decimal number (no sign handling needed beyond what from_chars does).
bool parseDouble(const std::string& s, double& out) {
    if (s.empty()) return false;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    if (end != s.data() + s.size()) return false;
    if (ec == std::errc()) return true;
    if (ec != std::errc::result_out_of_range) return false;
    // Overflow to inf, underflow to 0 or a subnormal, as Python gives: strtod in the C locale.
    locale_t c = newlocale(LC_ALL_MASK, "C", locale_t(0));
    if (c == locale_t(0)) return false;
    out = strtod_l(s.c_str(), nullptr, c);
    freelocale(c);
    return true;
}

// constructor.py construct_yaml_float. Returns "" or what is wrong.
std::string constructFloat(std::string_view text, double& out) {
    std::string v = withoutUnderscores(text);
    for (char& c : v)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    double sign = 1;
    if (!v.empty() && (v[0] == '-' || v[0] == '+')) {
        sign = v[0] == '-' ? -1 : 1;
        v.erase(0, 1);
    }
    bool ok = true;
    if (v == ".inf")
        out = std::numeric_limits<double>::infinity();
    else if (v == ".nan")
        out = std::numeric_limits<double>::quiet_NaN();
    else if (v.find(':') != std::string::npos) {  // sexagesimal: 190:20:30.15
        out = 0;
        std::size_t start = 0;
        while (ok) {
            const std::size_t colon = v.find(':', start);
            double part = 0;
            ok = parseDouble(v.substr(start, colon - start), part);
            out = out * 60 + part;
            if (colon == std::string::npos) break;
            start = colon + 1;
        }
    } else
        ok = parseDouble(v, out);
    if (!ok) return "'" + shortened(text) + "' is not a number";
    out *= sign;
    return {};
}

void setString(YamlNode& node) { node.kind = YamlNode::Kind::String; }

// The implicit resolvers, for a plain scalar (or one tagged '!').
std::string resolveImplicit(YamlNode& node) {
    const std::string_view s = node.text;
    if (isNullWord(s)) {
        node.kind = YamlNode::Kind::Null;
        return {};
    }
    if (isBoolWord(s, node.boolean)) {
        node.kind = YamlNode::Kind::Bool;
        return {};
    }
    if (matchesFloat(s)) {
        node.kind = YamlNode::Kind::Float;
        return constructFloat(s, node.number);
    }
    if (matchesInt(s)) {
        node.kind = YamlNode::Kind::Int;
        return constructInt(s, node.integer);
    }
    // PyYAML resolves these two to tags its safe constructor has no constructor for.
    if (s == "<<") return "merge keys ('<<') are not supported: write the merged keys out (or quote '<<')";
    if (s == "=") return "a plain '=' is YAML 1.1's value key, which a safe loader refuses: quote it";
    setString(node);  // timestamps (2001-12-14) included: PyYAML would make a date of them
    return {};
}

}  // namespace

std::string shortTag(std::string_view tag) {
    if (tag.rfind(kYamlTagPrefix, 0) == 0) return "!!" + shortened(tag.substr(kYamlTagPrefix.size()));
    return shortened(tag);
}

std::string resolve(YamlNode& node, std::string_view tag, bool plain) {
    if (tag.empty() || tag == "!") {
        if (plain || tag == "!") return resolveImplicit(node);  // PyYAML resolves '! x' as if plain
        setString(node);
        return {};
    }
    const std::string_view name = tag.rfind(kYamlTagPrefix, 0) == 0 ? tag.substr(kYamlTagPrefix.size()) : "";
    if (name == "str") {
        setString(node);
        return {};
    }
    if (name == "null") {  // construct_yaml_null ignores the text
        node.kind = YamlNode::Kind::Null;
        return {};
    }
    if (name == "bool") {
        std::string lower(node.text);
        for (char& c : lower)
            if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
        node.kind = YamlNode::Kind::Bool;
        if (isBoolWord(lower, node.boolean)) return {};
        return "'" + shortened(node.text) + "' is not a boolean (yes, no, true, false, on, off)";
    }
    if (name == "int") {
        node.kind = YamlNode::Kind::Int;
        return constructInt(node.text, node.integer);
    }
    if (name == "float") {
        node.kind = YamlNode::Kind::Float;
        return constructFloat(node.text, node.number);
    }
    if (name == "seq" || name == "map") return "the tag " + shortTag(tag) + " is given to a scalar";
    return "the tag " + shortTag(tag) + std::string(kRefusedTag);
}

}  // namespace shapevo::graph::yaml_scalar
