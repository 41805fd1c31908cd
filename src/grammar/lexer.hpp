// Lexer: splits grammar text into tokens that remember their line and column.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "grammar/grammar.hpp"

namespace shapevo {

enum class TokenKind { Identifier, Number, String, Punct, End };

struct Token {
    TokenKind kind = TokenKind::End;
    std::string text;      ///< identifier / string contents / the punctuation character
    double number = 0.0;
    SourceLocation where;
    bool is(char c) const { return kind == TokenKind::Punct && text.size() == 1 && text[0] == c; }
    /// Two-character punctuation: "<=", ">=", "==", "!=", "&&", "||".
    bool is(std::string_view p) const { return kind == TokenKind::Punct && text == p; }
    bool isWord(std::string_view w) const { return kind == TokenKind::Identifier && text == w; }
    std::string describe() const;  ///< "'foo'", "number 1.5", "end of file"
};

class Lexer {
public:
    Lexer(std::string_view text, std::string path) : text_(text), path_(std::move(path)) {}
    /// Next token; throws InputError on a character that starts no token.
    Token next();

private:
    void skipSpaceAndComments();
    char peek(std::size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
    void advance();

    std::string_view text_;
    std::string path_;
    std::size_t pos_ = 0;
    int line_ = 1, column_ = 1;
};

/// A lexer with one token of look-ahead and located errors; shared by the parser and the
/// expression compiler. Tokens are read lazily and kept, so the parser can return to a position
/// it has seen (mark / seek: rule bodies are compiled once per instance and per inline call);
/// lexical errors still come in source order.
class TokenStream {
public:
    TokenStream(std::string_view text, std::string path) : lexer_(text, path), path_(std::move(path)) {
        tokens_.push_back(lexer_.next());
    }
    const Token& peek() const { return tokens_[pos_]; }
    /// The token after the next one.
    const Token& peekSecond() {
        fill(pos_ + 1);
        return tokens_[pos_ + 1];
    }
    Token take() {
        Token t = tokens_[pos_];
        if (t.kind != TokenKind::End) {
            ++pos_;
            fill(pos_);
        }
        return t;
    }
    std::size_t mark() const { return pos_; }
    void seek(std::size_t position) { pos_ = position; }
    [[noreturn]] void fail(const SourceLocation& at, const std::string& message) const;
    /// Fail with "expected <what>, found <current token>".
    [[noreturn]] void expected(const std::string& what) const;
    void expect(char punct, const std::string& context);
    std::string expectIdentifier(const std::string& what);
    const std::string& path() const { return path_; }

private:
    void fill(std::size_t i) {
        while (tokens_.size() <= i) tokens_.push_back(tokens_.back().kind == TokenKind::End ? tokens_.back() : lexer_.next());
    }
    Lexer lexer_;
    std::string path_;
    std::vector<Token> tokens_;
    std::size_t pos_ = 0;
};

}  // namespace shapevo
