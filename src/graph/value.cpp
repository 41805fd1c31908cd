// Value's Python semantics (value.hpp): interning of attribute names, truthiness, == across
// types (ints and floats compared exactly, as Python does), and str()/repr() text — floats in
// Python's repr (shortest round-trip digits from std::to_chars, exponent form below 1e-4 and
// from 1e16 on), strings inside tuples in repr quotes.
#include "graph/value.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "graph/value_compare.hpp"

namespace shapevo::graph {

AttrKey AttrNames::intern(std::string_view name) {
    const AttrKey k = find(name);
    if (k != kNone) return k;
    names_.emplace_back(name);
    return AttrKey(names_.size() - 1);
}

AttrKey AttrNames::find(std::string_view name) const {
    for (std::size_t i = 0; i < names_.size(); ++i)
        if (names_[i] == name) return AttrKey(i);
    return kNone;
}

bool truthy(const Value& v) {
    switch (v.data.index()) {
        case 0: return false;
        case 1: return std::get<bool>(v.data);
        case 2: return std::get<std::int64_t>(v.data) != 0;
        case 3: return std::get<double>(v.data) != 0.0;  // nan is truthy, as in Python
        case 4: return !std::get<std::string>(v.data).empty();
        case 5: return !std::get<Tuple>(v.data)->empty();
        default: return true;  // a vector or an element (no __bool__ in the original)
    }
}

namespace value_detail {

// Exact comparison of an int with a float (Python compares the mathematical values).
// Returns -1, 0, 1, or 2 when unordered (nan).
int compareIntFloat(std::int64_t i, double d) {
    if (std::isnan(d)) return 2;
    if (d >= 9223372036854775808.0) return -1;
    if (d < -9223372036854775808.0) return 1;
    const double t = std::trunc(d);
    const auto ti = std::int64_t(t);
    if (i != ti) return i < ti ? -1 : 1;
    if (d == t) return 0;
    return d > t ? -1 : 1;  // same integer part: the fraction decides
}

}  // namespace value_detail

int compareNumbers(const Value& a, const Value& b) {
    // Callers pass numbers only (bool, int, float).
    const auto asIntLike = [](const Value& v, std::int64_t& out) {
        if (const bool* p = v.asBool()) return out = *p, true;
        if (const std::int64_t* p = v.asInt()) return out = *p, true;
        return false;
    };
    std::int64_t ia = 0, ib = 0;
    const bool aInt = asIntLike(a, ia), bInt = asIntLike(b, ib);
    if (aInt && bInt) return ia < ib ? -1 : (ia > ib ? 1 : 0);
    if (aInt) return value_detail::compareIntFloat(ia, *b.asFloat());
    if (bInt) {
        const int c = value_detail::compareIntFloat(ib, *a.asFloat());
        return c == 2 ? 2 : -c;
    }
    const double x = *a.asFloat(), y = *b.asFloat();
    if (x < y) return -1;
    if (x > y) return 1;
    if (x == y) return 0;
    return 2;
}

bool isNumber(const Value& v) {
    const std::size_t i = v.data.index();
    return i == 1 || i == 2 || i == 3;
}

bool equal(const Value& a, const Value& b) {
    if (isNumber(a) && isNumber(b)) return compareNumbers(a, b) == 0;
    if (a.data.index() != b.data.index()) return false;
    switch (a.data.index()) {
        case 0: return true;
        case 4: return *a.asString() == *b.asString();
        case 5: {
            const auto& x = **a.asTuple();
            const auto& y = **b.asTuple();
            if (x.size() != y.size()) return false;
            for (std::size_t i = 0; i < x.size(); ++i)
                if (!equal(x[i], y[i])) return false;
            return true;
        }
        case 6: return *a.asVec() == *b.asVec();
        case 7: return a.asElement()->attrs == b.asElement()->attrs && a.asElement()->isVertex == b.asElement()->isVertex;
        default: return false;
    }
}

void appendFloatRepr(std::string& out, double d) {
    if (std::isnan(d)) {
        out += "nan";
        return;
    }
    if (std::isinf(d)) {
        out += d < 0 ? "-inf" : "inf";
        return;
    }
    // Python writes fixed notation when the shortest digits' exponent is in [-4, 16): the same
    // digits std::to_chars gives in fixed form (1e-4 and 1e16 are where the exponent changes).
    const double magnitude = std::fabs(d);
    if (magnitude == 0 || (magnitude >= 1e-4 && magnitude < 1e16)) {
        char fixed[64];
        const auto f = std::to_chars(fixed, fixed + sizeof fixed, d, std::chars_format::fixed);
        const std::string_view text(fixed, std::size_t(f.ptr - fixed));
        out += text;
        if (text.find('.') == std::string_view::npos) out += ".0";
        return;
    }
    // Shortest round-trip digits in scientific form: [-]d[.ddd]e[+-]XX.
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, d, std::chars_format::scientific);
    const std::string_view sci(buf, std::size_t(r.ptr - buf));
    std::size_t pos = 0;
    if (sci[0] == '-') {
        out += '-';
        pos = 1;
    }
    const std::size_t e = sci.find('e');
    std::string digits;
    for (std::size_t i = pos; i < e; ++i)
        if (sci[i] != '.') digits += sci[i];
    int exponent = 0;
    std::from_chars(sci.data() + e + (sci[e + 1] == '+' ? 2 : 1), sci.data() + sci.size(), exponent);
    if (exponent < -4 || exponent >= 16) {
        // Python: mantissa, then e, sign and at least two exponent digits.
        out += digits[0];
        if (digits.size() > 1) {
            out += '.';
            out.append(digits, 1);
        }
        char ebuf[16];
        std::snprintf(ebuf, sizeof ebuf, "e%c%02d", exponent < 0 ? '-' : '+', exponent < 0 ? -exponent : exponent);
        out += ebuf;
        return;
    }
    if (exponent < 0) {
        out += "0.";
        out.append(std::size_t(-exponent - 1), '0');
        out += digits;
        return;
    }
    const std::size_t intDigits = std::size_t(exponent) + 1;
    if (digits.size() <= intDigits) {
        out += digits;
        out.append(intDigits - digits.size(), '0');
        out += ".0";
    } else {
        out.append(digits, 0, intDigits);
        out += '.';
        out.append(digits, intDigits);
    }
}

namespace {

void appendStringRepr(std::string& out, const std::string& s) {
    const bool hasSingle = s.find('\'') != std::string::npos;
    const char quote = hasSingle && s.find('"') == std::string::npos ? '"' : '\'';
    out += quote;
    for (const char ch : s) {
        const auto c = static_cast<unsigned char>(ch);
        if (ch == quote || ch == '\\') {
            out += '\\';
            out += ch;
        } else if (ch == '\n') {
            out += "\\n";
        } else if (ch == '\t') {
            out += "\\t";
        } else if (ch == '\r') {
            out += "\\r";
        } else if (c < 0x20 || c == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            out += buf;
        } else {
            out += ch;  // UTF-8 bytes of printable characters stay as they are
        }
    }
    out += quote;
}

void appendText(std::string& out, const Value& v, bool repr) {
    switch (v.data.index()) {
        case 0: out += "None"; return;
        case 1: out += *v.asBool() ? "True" : "False"; return;
        case 2: {
            char buf[32];
            const auto r = std::to_chars(buf, buf + sizeof buf, *v.asInt());
            out.append(buf, r.ptr);
            return;
        }
        case 3: appendFloatRepr(out, *v.asFloat()); return;
        case 4:
            if (repr)
                appendStringRepr(out, *v.asString());
            else
                out += *v.asString();
            return;
        case 5: {
            const auto& items = **v.asTuple();
            out += '(';
            for (std::size_t i = 0; i < items.size(); ++i) {
                if (i) out += ", ";
                appendText(out, items[i], true);
            }
            if (items.size() == 1) out += ',';
            out += ')';
            return;
        }
        case 6:
            out += "Vec(";
            appendFloatRepr(out, v.asVec()->x);
            out += ", ";
            appendFloatRepr(out, v.asVec()->y);
            out += ')';
            return;
        default: out += v.asElement()->isVertex ? "<vertex>" : "<edge>"; return;
    }
}

}  // namespace

void appendValueText(std::string& out, const Value& v) { appendText(out, v, false); }

std::string toText(const Value& v) {
    std::string out;
    appendText(out, v, false);
    return out;
}

const char* typeName(const Value& v) {
    static constexpr const char* kNames[] = {"NoneType", "bool", "int", "float", "str", "tuple", "Vec", "element"};
    return kNames[v.data.index()];
}

bool numberOf(const Value& v, double& out) {
    if (const bool* b = v.asBool()) return out = *b ? 1.0 : 0.0, true;
    if (const std::int64_t* i = v.asInt()) return out = double(*i), true;
    if (const double* d = v.asFloat()) return out = *d, true;
    return false;
}

}  // namespace shapevo::graph
