// Python's int(), float() and round() (expression_numeric.hpp). round(x, n) of a float rounds the
// exact binary value to n decimals half to even, as CPython does, through std::to_chars.
#include "graph/expression_numeric.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "graph/expression.hpp"
#include "graph/expression_lexer.hpp"

namespace shapevo::graph {
namespace numeric_detail {

std::string_view stripSpace(std::string_view s) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; };
    while (!s.empty() && space(s.front())) s.remove_prefix(1);
    while (!s.empty() && space(s.back())) s.remove_suffix(1);
    return s;
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Removes underscores that sit between two digits; false if any other underscore is present.
bool dropUnderscores(std::string_view s, std::string& out) {
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] != '_') {
            out += s[i];
            continue;
        }
        if (i == 0 || i + 1 >= s.size() || !isDigit(s[i - 1]) || !isDigit(s[i + 1])) return false;
    }
    return true;
}

[[noreturn]] void invalidInt(const std::string& s) {
    throw EvaluationError("invalid literal for int() with base 10: " + quoteForMessage(s));
}

std::int64_t parseInt(const std::string& text) {
    const std::string_view s = stripSpace(text);
    std::string clean;
    if (s.empty() || !dropUnderscores(s, clean)) invalidInt(text);
    std::size_t start = 0;
    const bool negative = clean[0] == '-';
    if (clean[0] == '-' || clean[0] == '+') start = 1;
    if (start >= clean.size()) invalidInt(text);
    for (std::size_t i = start; i < clean.size(); ++i)
        if (!isDigit(clean[i])) invalidInt(text);
    std::string digits = negative ? "-" : "";
    digits.append(clean, start);
    std::int64_t value = 0;
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (r.ec != std::errc()) throw EvaluationError("int() of " + quoteForMessage(text) + ": beyond 64 bits");
    return value;
}

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (char(a[i] | 0x20) != b[i]) return false;
    return true;
}

double parseFloat(const std::string& text) {
    std::string_view s = stripSpace(text);
    const auto invalid = [&] { return EvaluationError("could not convert string to float: " + quoteForMessage(text)); };
    bool negative = false;
    if (!s.empty() && (s[0] == '-' || s[0] == '+')) {
        negative = s[0] == '-';
        s.remove_prefix(1);
    }
    double value = 0;
    if (equalsIgnoringCase(s, "inf") || equalsIgnoringCase(s, "infinity")) {
        value = HUGE_VAL;
    } else if (equalsIgnoringCase(s, "nan")) {
        value = std::nan("");
    } else {
        std::string clean;
        if (s.empty() || !dropUnderscores(s, clean)) throw invalid();
        // Python's grammar: digits [. digits] [e [+-] digits], or . digits; from_chars's general
        // format accepts the same (and no hex, no inf here since those were handled above).
        bool digitSeen = false;
        for (const char c : clean) {
            if (isDigit(c)) digitSeen = true;
            if (c == 'e' || c == 'E') break;
        }
        if (!digitSeen || !(isDigit(clean[0]) || clean[0] == '.')) throw invalid();
        const auto r = std::from_chars(clean.data(), clean.data() + clean.size(), value);
        if (r.ptr != clean.data() + clean.size()) throw invalid();
        if (r.ec == std::errc::result_out_of_range) {
            const std::size_t e = clean.find_first_of("eE");
            value = e != std::string::npos && clean[e + 1] == '-' ? 0.0 : HUGE_VAL;
        } else if (r.ec != std::errc()) {
            throw invalid();
        }
    }
    return negative ? -value : value;
}

std::int64_t floatToInt(double d) {
    if (std::isnan(d)) throw EvaluationError("cannot convert float NaN to integer");
    if (std::isinf(d)) throw EvaluationError("cannot convert float infinity to integer");
    const double t = std::trunc(d);
    if (t >= 9223372036854775808.0 || t < -9223372036854775808.0)
        throw EvaluationError("int() of a float beyond 64 bits");
    return std::int64_t(t);
}

// Half to even at `ndigits` decimals (negative: tens, hundreds, ...) of an int.
std::int64_t roundInt(std::int64_t x, std::int64_t ndigits) {
    if (ndigits >= 0) return x;
    if (ndigits < -18) return 0;
    std::int64_t p = 1;
    for (std::int64_t i = 0; i < -ndigits; ++i) p *= 10;
    std::int64_t r = x % p;
    if (r < 0) r += p;  // Python's floor modulo
    std::int64_t q = 0;
    if (__builtin_sub_overflow(x, r, &q)) throw EvaluationError("integer overflow (beyond 64 bits)");
    const bool up = r > p - r || (r == p - r && (q / p) % 2 != 0);
    if (up && __builtin_add_overflow(q, p, &q)) throw EvaluationError("integer overflow (beyond 64 bits)");
    return q;
}

double roundFloat(double x, std::int64_t ndigits) {
    if (!std::isfinite(x) || x == 0) return x;
    if (ndigits > 323) return x;
    if (ndigits < -308) return std::copysign(0.0, x);
    if (ndigits >= 0) {
        char buf[1100];
        const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::fixed, int(ndigits));
        double y = 0;
        std::from_chars(buf, r.ptr, y);
        return y == 0 ? std::copysign(0.0, x) : y;
    }
    // Negative ndigits: the exact integer part's digits, rounded half to even at the cut.
    const double ip = std::trunc(std::fabs(x));
    const bool exactTie = std::fabs(x) == ip;
    char buf[400];
    const auto r = std::to_chars(buf, buf + sizeof buf, ip, std::chars_format::fixed, 0);
    std::string digits(buf, r.ptr);
    const std::size_t cut = std::size_t(-ndigits);
    if (cut > digits.size()) return std::copysign(0.0, x);
    std::string head = digits.substr(0, digits.size() - cut);
    const std::string tail = digits.substr(digits.size() - cut);
    const std::string half = "5" + std::string(cut - 1, '0');
    const int c = tail.compare(half);
    const bool headOdd = !head.empty() && (head.back() - '0') % 2 != 0;
    const bool up = c > 0 || (c == 0 && (!exactTie || headOdd));
    double y = head.empty() ? 0.0 : std::stod(head);
    if (up) y += 1;
    y *= std::pow(10.0, double(cut));
    return std::copysign(y, x);
}

}  // namespace numeric_detail

std::int64_t pythonInt(const Value& v) {
    using namespace numeric_detail;
    if (const std::int64_t* i = v.asInt()) return *i;
    if (const bool* b = v.asBool()) return *b ? 1 : 0;
    if (const double* d = v.asFloat()) return floatToInt(*d);
    if (const std::string* s = v.asString()) return parseInt(*s);
    throw EvaluationError(std::string("int() argument must be a string or a number, not '") + typeName(v) + "'");
}

double pythonFloat(const Value& v) {
    double d = 0;
    if (numberOf(v, d)) return d;
    if (const std::string* s = v.asString()) return numeric_detail::parseFloat(*s);
    throw EvaluationError(std::string("float() argument must be a string or a number, not '") + typeName(v) + "'");
}

void pythonRound(const Value& x, const Value* ndigits, Value& out) {
    using namespace numeric_detail;
    std::int64_t n = 0;
    if (ndigits && !ndigits->isNone()) {
        if (const std::int64_t* i = ndigits->asInt())
            n = *i;
        else if (const bool* b = ndigits->asBool())
            n = *b;
        else
            throw EvaluationError(std::string("round(): ndigits must be an int, not '") + typeName(*ndigits) + "'");
    } else {
        ndigits = nullptr;
    }
    if (const double* d = x.asFloat()) {
        if (ndigits) {
            out = Value(roundFloat(*d, n));
            return;
        }
        double r = std::round(*d);  // half away from zero, then ties to even as CPython does
        if (std::fabs(*d - r) == 0.5) r = 2.0 * std::round(*d / 2.0);
        out = Value(floatToInt(r));
        return;
    }
    if (x.asInt() || x.asBool()) {
        out = Value(roundInt(pythonInt(x), ndigits ? n : 0));
        return;
    }
    throw EvaluationError(std::string("type ") + typeName(x) + " doesn't define __round__ method");
}

}  // namespace shapevo::graph
