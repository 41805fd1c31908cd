// Lexer implementation: identifiers, numbers, strings, punctuation (one character, or one of
// <= >= == != && ||), # comments.
#include "grammar/lexer.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

#include "base/input_error.hpp"

namespace shapevo {

std::string Token::describe() const {
    switch (kind) {
    case TokenKind::Identifier: return "'" + text + "'";
    case TokenKind::Number: return "number " + text;
    case TokenKind::String: return "string \"" + text + "\"";
    case TokenKind::Punct: return "'" + text + "'";
    case TokenKind::End: return "end of file";
    }
    return "?";
}

void Lexer::advance() {
    if (text_[pos_] == '\n') {
        ++line_;
        column_ = 1;
    } else {
        ++column_;
    }
    ++pos_;
}

void Lexer::skipSpaceAndComments() {
    while (pos_ < text_.size()) {
        char c = text_[pos_];
        if (c == '#') {
            while (pos_ < text_.size() && text_[pos_] != '\n') advance();
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            advance();
        } else {
            break;
        }
    }
}

void TokenStream::fail(const SourceLocation& at, const std::string& message) const {
    throw InputError(path_, std::to_string(at.line) + ":" + std::to_string(at.column), message);
}

void TokenStream::expected(const std::string& what) const {
    fail(peek().where, "expected " + what + ", found " + peek().describe());
}

void TokenStream::expect(char punct, const std::string& context) {
    if (!peek().is(punct)) expected(std::string("'") + punct + "' " + context);
    take();
}

std::string TokenStream::expectIdentifier(const std::string& what) {
    if (peek().kind != TokenKind::Identifier) expected(what);
    return take().text;
}

Token Lexer::next() {
    skipSpaceAndComments();
    Token t;
    t.where = {line_, column_};
    if (pos_ >= text_.size()) return t;
    const char c = text_[pos_];
    const auto where = std::to_string(line_) + ":" + std::to_string(column_);
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        t.kind = TokenKind::Identifier;
        while (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_') {
            t.text += peek();
            advance();
        }
        return t;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && std::isdigit(static_cast<unsigned char>(peek(1))))) {
        t.kind = TokenKind::Number;
        while (std::isdigit(static_cast<unsigned char>(peek())) || peek() == '.') {
            t.text += peek();
            advance();
        }
        if ((peek() == 'e' || peek() == 'E') &&
            (std::isdigit(static_cast<unsigned char>(peek(1))) ||
             ((peek(1) == '-' || peek(1) == '+') && std::isdigit(static_cast<unsigned char>(peek(2)))))) {
            t.text += peek();
            advance();
            t.text += peek();
            advance();
            while (std::isdigit(static_cast<unsigned char>(peek()))) {
                t.text += peek();
                advance();
            }
        }
        auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), t.number);
        if (ec == std::errc::result_out_of_range ||
            (ec == std::errc() && !(std::fabs(t.number) <= double(std::numeric_limits<float>::max()))))
            throw InputError(path_, where, "number '" + t.text + "' is out of range (values are 32-bit floats, "
                                           "at most about 3.4e38 in magnitude)");
        if (ec != std::errc() || end != t.text.data() + t.text.size())
            throw InputError(path_, where, "malformed number '" + t.text + "'");
        return t;
    }
    if (c == '"') {
        t.kind = TokenKind::String;
        advance();
        while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != '\n') {
            t.text += text_[pos_];
            advance();
        }
        if (pos_ >= text_.size() || text_[pos_] != '"')
            throw InputError(path_, where, "string is not closed before the end of the line");
        advance();
        return t;
    }
    static constexpr std::string_view kPairs[] = {"<=", ">=", "==", "!=", "&&", "||"};
    for (std::string_view pair : kPairs) {
        if (c == pair[0] && peek(1) == pair[1]) {
            t.kind = TokenKind::Punct;
            t.text = std::string(pair);
            advance();
            advance();
            return t;
        }
    }
    static constexpr std::string_view kPunct = "{}()[],=|.+-*/<>!'~:";
    if (kPunct.find(c) != std::string_view::npos) {
        t.kind = TokenKind::Punct;
        t.text = std::string(1, c);
        advance();
        return t;
    }
    std::string shown = std::isprint(static_cast<unsigned char>(c)) ? std::string(1, c)
                                                                    : "byte " + std::to_string(int(static_cast<unsigned char>(c)));
    throw InputError(path_, where, "unexpected character '" + shown + "'");
}

}  // namespace shapevo
