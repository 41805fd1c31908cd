// The expression language's tokenizer (expression_lexer.hpp): Python's literal forms, names and
// operators, each fault an ExpressionError at its byte offset.
#include "graph/expression_lexer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "graph/expression.hpp"

namespace shapevo::graph {
namespace lexer_detail {

bool isIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isIdentChar(char c) { return isIdentStart(c) || (c >= '0' && c <= '9'); }
bool isDigitOf(char c, int base) {
    if (base == 16) return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
    return c >= '0' && c < char('0' + base);
}
int digitValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return c - 'A' + 10;
}

void appendUtf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += char(cp);
    } else if (cp < 0x800) {
        out += char(0xc0 | (cp >> 6));
        out += char(0x80 | (cp & 0x3f));
    } else if (cp < 0x10000) {
        out += char(0xe0 | (cp >> 12));
        out += char(0x80 | ((cp >> 6) & 0x3f));
        out += char(0x80 | (cp & 0x3f));
    } else {
        out += char(0xf0 | (cp >> 18));
        out += char(0x80 | ((cp >> 12) & 0x3f));
        out += char(0x80 | ((cp >> 6) & 0x3f));
        out += char(0x80 | (cp & 0x3f));
    }
}

class Lexer {
public:
    Lexer(std::string_view text, std::size_t begin, std::size_t end) : text_(text), pos_(begin), end_(end) {}

    std::vector<Token> run() {
        std::vector<Token> tokens;
        for (;;) {
            skipSpace();
            Token t;
            t.offset = std::uint32_t(pos_);
            if (pos_ >= end_) {
                tokens.push_back(std::move(t));
                return tokens;
            }
            const char c = text_[pos_];
            if ((c >= '0' && c <= '9') || (c == '.' && pos_ + 1 < end_ && text_[pos_ + 1] >= '0' && text_[pos_ + 1] <= '9'))
                number(t);
            else if (c == '\'' || c == '"')
                string(t, pos_, false, false);
            else if (isIdentStart(c))
                nameOrPrefixedString(t);
            else
                punct(t);
            tokens.push_back(std::move(t));
        }
    }

private:
    [[noreturn]] void fail(const std::string& what, std::size_t at) const { throw ExpressionError(what, at); }

    void skipSpace() {
        while (pos_ < end_) {
            const char c = text_[pos_];
            if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f') {
                ++pos_;
            } else if (c == '#') {  // a comment runs to the end of its line
                while (pos_ < end_ && text_[pos_] != '\n') ++pos_;
            } else if (c == '\\' && pos_ + 1 < end_ && text_[pos_ + 1] == '\n') {
                pos_ += 2;  // explicit line joining
            } else {
                return;
            }
        }
    }

    void number(Token& t) {
        const std::size_t start = pos_;
        const char* what = "decimal";
        int base = 10;
        if (text_[pos_] == '0' && pos_ + 1 < end_) {
            const char p = char(text_[pos_ + 1] | 0x20);
            if (p == 'x') base = 16, what = "hexadecimal";
            if (p == 'o') base = 8, what = "octal";
            if (p == 'b') base = 2, what = "binary";
        }
        if (base != 10) {
            pos_ += 2;
            std::uint64_t value = 0;
            bool any = false;
            while (pos_ < end_ && (isDigitOf(text_[pos_], base) || text_[pos_] == '_')) {
                if (text_[pos_] == '_') {
                    if (pos_ + 1 >= end_ || !isDigitOf(text_[pos_ + 1], base)) fail(std::string("invalid ") + what + " literal", pos_);
                    ++pos_;
                    continue;
                }
                if (value > (std::uint64_t(INT64_MAX) - std::uint64_t(digitValue(text_[pos_]))) / std::uint64_t(base))
                    fail("integer literal too large (beyond 64 bits)", start);
                value = value * std::uint64_t(base) + std::uint64_t(digitValue(text_[pos_]));
                any = true;
                ++pos_;
            }
            if (!any) fail(std::string("invalid ") + what + " literal", start);
            checkNumberEnd(start);
            t.kind = TokenKind::Int;
            t.intValue = std::int64_t(value);
            t.text = text_.substr(start, pos_ - start);
            return;
        }
        std::string clean;
        bool isFloat = false;
        digits(clean);
        if (pos_ < end_ && text_[pos_] == '.') {
            isFloat = true;
            clean += '.';
            ++pos_;
            if (pos_ < end_ && text_[pos_] >= '0' && text_[pos_] <= '9') digits(clean);
        }
        bool negativeExponent = false;
        if (pos_ < end_ && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
            std::size_t p = pos_ + 1;
            if (p < end_ && (text_[p] == '+' || text_[p] == '-')) negativeExponent = text_[p++] == '-';
            if (p < end_ && text_[p] >= '0' && text_[p] <= '9') {
                isFloat = true;
                clean += text_.substr(pos_, p - pos_);
                pos_ = p;
                digits(clean);
            }
        }
        checkNumberEnd(start);
        t.text = text_.substr(start, pos_ - start);
        if (isFloat) {
            t.kind = TokenKind::Float;
            const auto r = std::from_chars(clean.data(), clean.data() + clean.size(), t.floatValue);
            if (r.ec == std::errc::result_out_of_range) t.floatValue = negativeExponent ? 0.0 : HUGE_VAL;
            return;
        }
        if (clean.size() > 1 && clean[0] == '0' && clean.find_first_not_of('0') != std::string::npos)
            fail("leading zeros in decimal integer literals are not permitted", start);
        t.kind = TokenKind::Int;
        const auto r = std::from_chars(clean.data(), clean.data() + clean.size(), t.intValue);
        if (r.ec != std::errc()) fail("integer literal too large (beyond 64 bits)", start);
    }

    void digits(std::string& clean) {
        while (pos_ < end_) {
            const char c = text_[pos_];
            if (c >= '0' && c <= '9') {
                clean += c;
                ++pos_;
            } else if (c == '_' && pos_ + 1 < end_ && text_[pos_ + 1] >= '0' && text_[pos_ + 1] <= '9' && !clean.empty()) {
                ++pos_;
            } else {
                return;
            }
        }
    }

    void checkNumberEnd(std::size_t start) {
        if (pos_ < end_ && isIdentChar(text_[pos_])) {
            if (text_[pos_] == 'j' || text_[pos_] == 'J') fail("imaginary numbers are not supported", pos_);
            fail("invalid number literal " + quoteForMessage(text_.substr(start, pos_ + 1 - start)), start);
        }
    }

    void nameOrPrefixedString(Token& t) {
        const std::size_t start = pos_;
        while (pos_ < end_ && isIdentChar(text_[pos_])) ++pos_;
        const std::string_view name = text_.substr(start, pos_ - start);
        if (pos_ < end_ && (text_[pos_] == '\'' || text_[pos_] == '"') && name.size() <= 2) {
            if (name == "r" || name == "R") return string(t, start, true, false);
            if (name == "u" || name == "U") return string(t, start, false, false);
            if (name == "f" || name == "F") return string(t, start, false, true);
            fail("string prefix " + quoteForMessage(name) + " is not supported", start);
        }
        t.kind = TokenKind::Name;
        t.text = name;
    }

    // The literal starting at `start` (its prefix, if any, ends at pos_).
    void string(Token& t, std::size_t start, bool raw, bool formatted) {
        const char quote = text_[pos_];
        const std::size_t bodyStart = ++pos_;
        for (;;) {
            if (pos_ >= end_ || text_[pos_] == '\n') fail("unterminated string literal", start);
            const char c = text_[pos_];
            if (c == '\\') {
                pos_ += 2;
                continue;
            }
            if (c == quote) break;
            ++pos_;
        }
        const std::string_view body = text_.substr(bodyStart, pos_ - bodyStart);
        ++pos_;
        t.offset = std::uint32_t(start);
        if (formatted) {
            t.kind = TokenKind::FString;
            t.text = body;
            t.intValue = std::int64_t(bodyStart);
            return;
        }
        t.kind = TokenKind::String;
        t.text = text_.substr(start, pos_ - start);
        if (raw)
            t.stringValue = std::string(body);
        else
            decodeStringEscapes(body, bodyStart, t.stringValue);
    }

    void punct(Token& t) {
        static constexpr std::string_view kTwo[] = {"//", "==", "!=", "<=", ">=", "**", "<<", ">>", "->", ":="};
        t.kind = TokenKind::Punct;
        if (pos_ + 1 < end_)
            for (const std::string_view two : kTwo)
                if (text_.substr(pos_, 2) == two) {
                    t.text = text_.substr(pos_, 2);
                    pos_ += 2;
                    return;
                }
        static constexpr std::string_view kOne = "+-*/%<>()[]{},.=:;@~&|^!";
        if (kOne.find(text_[pos_]) == std::string_view::npos)
            fail("unexpected character " + quoteForMessage(text_.substr(pos_, 1)), pos_);
        t.text = text_.substr(pos_, 1);
        ++pos_;
    }

    std::string_view text_;
    std::size_t pos_, end_;
};

}  // namespace lexer_detail

std::vector<Token> tokenize(std::string_view text, std::size_t begin, std::size_t end) {
    return lexer_detail::Lexer(text, begin, end).run();
}

void decodeStringEscapes(std::string_view body, std::size_t offset, std::string& out) {
    using namespace lexer_detail;
    for (std::size_t i = 0; i < body.size(); ++i) {
        if (body[i] != '\\' || i + 1 >= body.size()) {
            out += body[i];
            continue;
        }
        const std::size_t at = i;
        const char e = body[++i];
        switch (e) {
            case '\n': break;
            case '\\': out += '\\'; break;
            case '\'': out += '\''; break;
            case '"': out += '"'; break;
            case 'a': out += '\a'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            case 'v': out += '\v'; break;
            case 'x':
            case 'u':
            case 'U': {
                const std::size_t n = e == 'x' ? 2 : (e == 'u' ? 4 : 8);
                std::uint32_t cp = 0;
                for (std::size_t k = 1; k <= n; ++k) {
                    if (i + k >= body.size() || !isDigitOf(body[i + k], 16))
                        throw ExpressionError(std::string("truncated \\") + e + " escape in a string", offset + at);
                    cp = cp * 16 + std::uint32_t(digitValue(body[i + k]));
                }
                if (cp > 0x10ffff) throw ExpressionError("\\U escape beyond U+10FFFF in a string", offset + at);
                appendUtf8(out, cp);
                i += n;
                break;
            }
            case 'N': throw ExpressionError("\\N{...} escapes are not supported", offset + at);
            default:
                if (e >= '0' && e <= '7') {
                    std::uint32_t cp = 0;
                    std::size_t k = 0;
                    while (k < 3 && i + k < body.size() && body[i + k] >= '0' && body[i + k] <= '7')
                        cp = cp * 8 + std::uint32_t(body[i + k++] - '0');
                    appendUtf8(out, cp);
                    i += k - 1;
                } else {
                    out += '\\';  // Python keeps an unknown escape as it is
                    out += e;
                }
        }
    }
}

std::string quoteForMessage(std::string_view text) {
    std::string out = "'";
    const std::size_t n = text.size() > 40 ? 40 : text.size();
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 || c >= 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            out += buf;
        } else {
            out += char(c);
        }
    }
    if (n < text.size()) out += "...";
    return out + "'";
}

}  // namespace shapevo::graph
