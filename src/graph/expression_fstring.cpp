// String literals in the parser (expression_parser.hpp): adjacent literals concatenate, as in
// Python ('a' 'b' is 'ab'); an f-string's body splits into literal text ({{ and }} escaped) and
// {expression} fields, each parsed by its own Parser at the next depth. A conversion (!r) or a
// format spec (:...) is a compile error; a field's value is formatted as str() (floats as repr).
#include <string>

#include "graph/expression_parser.hpp"

namespace shapevo::graph {

std::int32_t Parser::parseStrings() {
    const std::size_t at = peek().offset;
    std::string literal;
    std::vector<std::int32_t> parts;
    bool formatted = false;
    while (peek().kind == TokenKind::String || peek().kind == TokenKind::FString) {
        const Token& t = take();
        if (t.kind == TokenKind::String) {
            literal += t.stringValue;
        } else {
            formatted = true;
            fstringParts(t, literal, parts);
        }
    }
    if (!formatted) return constant(Value(std::move(literal)), at);
    if (!literal.empty()) parts.push_back(constant(Value(std::move(literal)), at));
    if (parts.empty()) return constant(Value(std::string()), at);
    return addList(Op::Format, 0, parts, at);
}

void Parser::fstringParts(const Token& t, std::string& literal, std::vector<std::int32_t>& parts) {
    const std::string_view body = t.text;
    const auto bodyStart = std::size_t(t.intValue);
    std::string raw;  // literal characters not yet escape-decoded
    std::size_t rawStart = bodyStart;
    const auto flush = [&] {
        decodeStringEscapes(raw, rawStart, literal);
        raw.clear();
    };
    std::size_t i = 0;
    while (i < body.size()) {
        const char c = body[i];
        if (c == '\\' && i + 1 < body.size() && body[i + 1] != '{' && body[i + 1] != '}') {
            if (raw.empty()) rawStart = bodyStart + i;
            raw += body.substr(i, 2);
            i += 2;
            continue;
        }
        if (c == '}') {
            if (i + 1 < body.size() && body[i + 1] == '}') {
                raw += '}';
                i += 2;
                continue;
            }
            fail("f-string: single '}' is not allowed", bodyStart + i);
        }
        if (c != '{') {
            if (raw.empty()) rawStart = bodyStart + i;
            raw += c;
            ++i;
            continue;
        }
        if (i + 1 < body.size() && body[i + 1] == '{') {
            raw += '{';
            i += 2;
            continue;
        }
        // A field: find its closing brace at nesting 0, outside inner strings.
        flush();
        std::size_t j = i + 1;
        int nest = 0;
        char quote = 0;
        for (; j < body.size(); ++j) {
            const char d = body[j];
            if (quote) {
                if (d == quote) quote = 0;
                continue;
            }
            if (d == '\'' || d == '"') {
                quote = d;
            } else if (d == '\\') {
                fail("f-string: a backslash inside {expression} is not allowed", bodyStart + j);
            } else if (d == '(' || d == '[' || d == '{') {
                ++nest;
            } else if (d == ')' || d == ']' || d == '}') {
                if (nest == 0) {
                    if (d == '}') break;
                    fail("f-string: unmatched '" + std::string(1, d) + "'", bodyStart + j);
                }
                --nest;
            } else if (nest == 0 && d == '!' && (j + 1 >= body.size() || body[j + 1] != '=')) {
                fail("f-string conversions ('!" + std::string(body.substr(j + 1, 1)) + "') are not supported",
                     bodyStart + j);
            } else if (nest == 0 && d == ':') {
                fail("f-string format specs (':') are not supported", bodyStart + j);
            } else if (d == '!' || d == '=' || d == '<' || d == '>') {
                if (j + 1 < body.size() && body[j + 1] == '=') ++j;  // keep != == <= >= whole
            }
        }
        if (j >= body.size()) fail("f-string: expecting '}'", bodyStart + i);
        if (body.substr(i + 1, j - i - 1).find_first_not_of(" \t\n\r\f") == std::string_view::npos)
            fail("f-string: empty expression not allowed", bodyStart + i);
        if (!literal.empty()) {
            parts.push_back(constant(Value(std::move(literal)), bodyStart + i));
            literal.clear();
        }
        Parser field(text_, bodyStart + i + 1, bodyStart + j, context_, depth_);
        parts.push_back(field.parseAll());
        i = j + 1;
    }
    flush();
}

}  // namespace shapevo::graph
