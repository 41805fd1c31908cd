// The tokens of the expression language (internal to the expression files): Python's numbers
// (decimal, 0x/0o/0b, underscores, floats with exponents), strings with Python's escapes and an
// r/f prefix, names and operators. Every token knows its byte offset; every fault is an
// ExpressionError naming what it met.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace shapevo::graph {

enum class TokenKind : std::uint8_t { End, Int, Float, String, FString, Name, Punct };

struct Token {
    TokenKind kind = TokenKind::End;
    std::uint32_t offset = 0;  // first byte, in the whole text
    std::string_view text;     // the token's source text (for FString: the body between the quotes)
    std::int64_t intValue = 0;
    double floatValue = 0;
    std::string stringValue;   // a String's decoded characters
};

/// Splits text[begin, end) into tokens (the last one End). Offsets count from text's start.
std::vector<Token> tokenize(std::string_view text, std::size_t begin, std::size_t end);

/// Appends `body` (a string literal's characters between its quotes, at byte `offset` of the
/// text) to `out` with Python's escapes decoded; unknown escapes stay as backslash + character.
void decodeStringEscapes(std::string_view body, std::size_t offset, std::string& out);

/// A token's text for messages: quoted, cut to a few dozen characters, control bytes escaped.
std::string quoteForMessage(std::string_view text);

}  // namespace shapevo::graph
