// A `.pcg` expression's tokens written back as shapevo-language text, with an included graph's
// names (its params and attrs) renamed to their instance's names. Names after a '.' (scope.size.x)
// are never renamed.
#pragma once
#include <map>
#include <string>

#include "grammar/pcg/pcg_syntax.hpp"

namespace shapevo::pcg {

using Renames = std::map<std::string, std::string>;

inline std::string expressionText(const Expr& e, const Renames& rename) {
    std::string s;
    const Token* prev = nullptr;
    for (const Token& t : e.tokens) {
        std::string piece = t.text;
        if (t.kind == TokenKind::String) piece = "\"" + t.text + "\"";
        if (t.kind == TokenKind::Identifier && !(prev && prev->is('.'))) {
            const auto it = rename.find(t.text);
            if (it != rename.end()) piece = it->second;
        }
        const bool call = t.is('(') && prev && prev->kind == TokenKind::Identifier;  // uniform(0, 1)
        const bool tight = call || t.is('.') || t.is(',') || t.is(')') || t.is(']') ||
                           (prev && (prev->is('.') || prev->is('(') || prev->is('[') || prev->is('\'') || prev->is('~')));
        if (prev && !tight) s += ' ';
        s += piece;
        prev = &t;
    }
    return s;
}

}  // namespace shapevo::pcg
