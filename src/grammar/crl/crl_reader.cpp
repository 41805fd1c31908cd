// CRL reader: tokens and the form of a rule file (crl_syntax.hpp). Accepts both arrows, `->`
// and `→`; comments `//`, `/* */` and `#` (except `#include`); successors in braces separated by
// `|` (or `,`, as the thesis's §3.7.4 writes them), or one bare handle after the call (as in
// chapter 4's `scale(1, 1, 1.4) ScaledTower`).
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "base/input_error.hpp"
#include "grammar/crl/crl_syntax.hpp"

namespace shapevo::crl {

namespace {

enum class Kind { Word, Number, String, Punct, Arrow, End };
struct Token {
    Kind kind = Kind::End;
    std::string text;
    double number = 0;
    int line = 1, column = 1;
    bool is(char c) const { return kind == Kind::Punct && text.size() == 1 && text[0] == c; }
    bool isWord(const char* w) const { return kind == Kind::Word && text == w; }
};

std::string describe(const Token& t) {
    switch (t.kind) {
    case Kind::Word: return "'" + shortened(t.text) + "'";
    case Kind::Number: return "number " + shortened(t.text);
    case Kind::String: return "string \"" + shortened(t.text) + "\"";
    case Kind::Punct: return "'" + t.text + "'";
    case Kind::Arrow: return "'->'";
    case Kind::End: return "end of file";
    }
    return "?";
}

class Reader {
public:
    Reader(const std::string& text, const std::string& path) : text_(text), path_(path) { advance(); }

    File run() {
        File f;
        f.path = path_;
        while (tok_.kind != Kind::End) item(f);
        return f;
    }

private:
    [[noreturn]] void fail(int line, int column, const std::string& what) const {
        throw InputError(path_, std::to_string(line) + ":" + std::to_string(column), what);
    }
    [[noreturn]] void fail(const Token& t, const std::string& what) const { fail(t.line, t.column, what); }
    [[noreturn]] void expected(const std::string& what) const { fail(tok_, "expected " + what + ", found " + describe(tok_)); }
    Location here() const { return {path_, tok_.line, tok_.column}; }

    // --- lexer -------------------------------------------------------------------------------
    char at(std::size_t k = 0) const { return pos_ + k < text_.size() ? text_[pos_ + k] : '\0'; }
    void step() {
        if (at() == '\n') {
            ++line_;
            column_ = 1;
        } else if ((static_cast<unsigned char>(at()) & 0xC0) != 0x80) {
            ++column_;  // columns count characters; continuation bytes of UTF-8 do not
        }
        ++pos_;
    }
    void skip() {
        while (pos_ < text_.size()) {
            const char c = at();
            if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
                step();
            } else if (c == '/' && at(1) == '/') {
                while (pos_ < text_.size() && at() != '\n') step();
            } else if (c == '#' && text_.compare(pos_, 8, "#include") != 0) {
                while (pos_ < text_.size() && at() != '\n') step();
            } else if (c == '/' && at(1) == '*') {
                const int l = line_, col = column_;
                step();
                step();
                while (pos_ < text_.size() && !(at() == '*' && at(1) == '/')) step();
                if (pos_ >= text_.size()) fail(l, col, "comment '/*' is never closed");
                step();
                step();
            } else {
                break;
            }
        }
    }
    void advance() {
        endLine_ = line_;  // just past the token being left
        endColumn_ = column_;
        skip();
        Token t;
        t.line = line_;
        t.column = column_;
        if (pos_ >= text_.size()) {
            tok_ = t;
            return;
        }
        const char c = at();
        const auto start = pos_;
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_' || (c == '#' && text_.compare(pos_, 8, "#include") == 0)) {
            step();
            while (std::isalnum(static_cast<unsigned char>(at())) || at() == '_') step();
            t.kind = Kind::Word;
            t.text = text_.substr(start, pos_ - start);
        } else if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && std::isdigit(static_cast<unsigned char>(at(1))))) {
            while (std::isdigit(static_cast<unsigned char>(at()))) step();
            if (at() == '.') {
                step();
                while (std::isdigit(static_cast<unsigned char>(at()))) step();
            }
            if ((at() == 'e' || at() == 'E') &&
                (std::isdigit(static_cast<unsigned char>(at(1))) ||
                 ((at(1) == '+' || at(1) == '-') && std::isdigit(static_cast<unsigned char>(at(2)))))) {
                step();
                if (at() == '+' || at() == '-') step();
                while (std::isdigit(static_cast<unsigned char>(at()))) step();
            }
            if (std::isalnum(static_cast<unsigned char>(at())) || at() == '_' || at() == '.') {
                std::size_t stop = pos_;  // show the whole run, as in 1.2.3 or 3x
                while (stop < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[stop])) || text_[stop] == '_' || text_[stop] == '.')) ++stop;
                fail(t.line, t.column, "malformed number '" + shortened(text_.substr(start, stop - start)) + "'");
            }
            t.kind = Kind::Number;
            t.text = text_.substr(start, pos_ - start);
            t.number = std::strtod(t.text.c_str(), nullptr);
            if (!std::isfinite(t.number) || std::fabs(t.number) > 3.4e38)
                fail(t.line, t.column, "number " + shortened(t.text) + " is too large");
        } else if (c == '"') {
            step();
            while (pos_ < text_.size() && at() != '"' && at() != '\n') step();
            if (at() != '"') fail(t.line, t.column, "string is not closed on its line");
            t.kind = Kind::String;
            t.text = text_.substr(start + 1, pos_ - start - 1);
            step();
        } else if (c == '-' && at(1) == '>') {
            step();
            step();
            t.kind = Kind::Arrow;
            t.text = "->";
        } else if (static_cast<unsigned char>(c) == 0xE2 && static_cast<unsigned char>(at(1)) == 0x86 &&
                   static_cast<unsigned char>(at(2)) == 0x92) {  // → U+2192
            step();
            step();
            step();
            t.kind = Kind::Arrow;
            t.text = "->";
        } else if (std::string_view("(){}[],;|=-+").find(c) != std::string_view::npos) {
            step();
            t.kind = Kind::Punct;
            t.text = std::string(1, c);
        } else {
            const unsigned char u = static_cast<unsigned char>(c);
            fail(t.line, t.column, u >= 0x20 && u < 0x7f ? std::string("unexpected character '") + c + "'"
                                                         : "unexpected byte 0x" + std::string(1, "0123456789abcdef"[u >> 4]) +
                                                               "0123456789abcdef"[u & 15]);
        }
        tok_ = t;
    }
    Token take() {
        Token t = tok_;
        advance();
        return t;
    }
    void expect(char c, const std::string& what) {
        if (!tok_.is(c)) expected(std::string("'") + c + "' " + what);
        advance();
    }
    /// The ';' that ends a rule or an attr. A missing one is reported just past the statement's
    /// last token when the next token is on a later line; a bare successor that is really the
    /// handle of the next rule (`L = rect(...)` then `L -> ...`) is reported as such.
    void endStatement(const std::string& what) {
        if (tok_.is(';')) return advance();
        if (bare_ && (tok_.kind == Kind::Arrow || tok_.is('=')))
            fail(bareEnd_.line, bareEnd_.column, "expected ';' " + what + ", found '" + shortened(bareHandle_.text) + "' at line " +
                                                     std::to_string(bareHandle_.line) + ", which starts the next rule");
        if (tok_.line > endLine_) fail(endLine_, endColumn_, "expected ';' " + what + ", found " + describe(tok_) + " at line " + std::to_string(tok_.line));
        expected("';' " + what);
    }

    // --- parser ------------------------------------------------------------------------------
    static bool isHandle(const std::string& w) { return !w.empty() && std::isupper(static_cast<unsigned char>(w[0])); }

    double signedNumber(const std::string& what) {
        double sign = 1;
        if (tok_.is('-') || tok_.is('+')) sign = take().text == "-" ? -1 : 1;
        if (tok_.kind != Kind::Number) expected(what);
        return sign * take().number;
    }

    Arg bound() {
        Arg a;
        a.where = here();
        if (tok_.kind == Kind::Word && !tok_.isWord("rand")) {
            a.kind = ArgKind::Name;
            a.text = take().text;
        } else {
            a.number = signedNumber("a number or an attr name as a bound of rand(a, b)");
        }
        return a;
    }

    Arg argument() {
        Arg a;
        a.where = here();
        if (tok_.kind == Kind::String) {
            a.kind = ArgKind::String;
            a.text = take().text;
        } else if (tok_.isWord("rand")) {
            take();
            a.kind = ArgKind::Rand;
            expect('(', "after rand (rand(a, b))");
            a.bounds.push_back(bound());
            expect(',', "between the bounds of rand(a, b)");
            a.bounds.push_back(bound());
            expect(')', "to close rand(a, b)");
        } else if (tok_.kind == Kind::Word) {
            if (isHandle(tok_.text)) fail(tok_, "expected an argument (a number, an attr, rand(a, b) or a \"string\"), found handle '" +
                                                    shortened(tok_.text) + "'");
            a.kind = ArgKind::Name;
            a.text = take().text;
        } else if (tok_.kind == Kind::Number || tok_.is('-') || tok_.is('+')) {
            a.number = signedNumber("a number after the sign");
        } else {
            expected("an argument (a number, an attr, rand(a, b) or a \"string\")");
        }
        return a;
    }

    Application application() {
        Application app;
        bare_ = false;
        if (tok_.is('[')) {
            app.weighted = true;
            take();
            app.probabilityAt = here();
            app.probability = signedNumber("a probability in [ ] (a number)");
            expect(']', "after the probability");
        }
        app.where = here();
        if (tok_.kind != Kind::Word) expected("a function (extrude, comp, split, insert, ...)");
        if (isHandle(tok_.text))
            fail(tok_, "expected a function after the arrow, found handle '" + shortened(tok_.text) +
                           "' (a rule is Pred -> function(args) {Succ};)");
        app.function = take().text;
        expect('(', "after the function's name");
        if (!tok_.is(')')) {
            app.args.push_back(argument());
            while (tok_.is(',')) {
                take();
                app.args.push_back(argument());
            }
        }
        expect(')', "to close the arguments (or ',' before the next one)");
        if (tok_.is('{')) {
            const Token open = take();
            while (true) {
                if (tok_.kind != Kind::Word || !isHandle(tok_.text))
                    expected("a successor handle (a name starting with a capital letter)");
                app.successors.push_back({tok_.text, here()});
                take();
                if (tok_.is('|') || tok_.is(',')) {
                    take();
                    continue;
                }
                if (tok_.is('}')) break;
                expected("'|' between successors or '}' to close those opened at line " + std::to_string(open.line));
            }
            take();
        } else if (tok_.kind == Kind::Word && isHandle(tok_.text)) {
            app.successors.push_back({tok_.text, here()});
            bareEnd_ = {path_, endLine_, endColumn_};
            bareHandle_ = take();
            bare_ = true;
        }
        return app;
    }

    void item(File& f) {
        bare_ = false;
        if (tok_.isWord("attr")) {
            take();
            Attr a;
            a.where = here();
            if (tok_.kind != Kind::Word) expected("an attr name after 'attr'");
            a.name = take().text;
            for (char c : a.name)
                if (!(std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_'))
                    fail(a.where.line, a.where.column, "attr names are lowercase letters, digits and '_' (castlemaker-crl.txt §3.6.5), found '" +
                                                           shortened(a.name) + "'");
            expect('=', "after the attr name");
            a.value = signedNumber("the attr's value (a number)");
            endStatement("after the attr definition");
            f.attrs.push_back(a);
            return;
        }
        if (tok_.isWord("include") || tok_.isWord("#include")) {
            take();
            Include inc;
            inc.where = here();
            if (tok_.kind != Kind::String) expected("a file name in quotes after include");
            inc.path = take().text;
            if (tok_.is(';')) take();
            f.includes.push_back(inc);
            return;
        }
        if (tok_.kind != Kind::Word) expected("a rule (Handle -> function(...) {...};), a lot (Handle = rect(...);), attr or include");
        if (!isHandle(tok_.text))
            fail(tok_, "a rule starts with a handle, a name with a capital first letter (castlemaker-crl.txt §3.6.2), found '" +
                           shortened(tok_.text) + "'");
        RuleDef r;
        r.where = here();
        r.predecessor = take().text;
        if (tok_.is('=')) {
            take();
            r.direct = true;
            r.alternatives.push_back(application());
            if (r.alternatives[0].weighted) fail(r.alternatives[0].probabilityAt.line, r.alternatives[0].probabilityAt.column,
                                                 "a direct lot (Handle = rect(...)) has no probability");
        } else if (tok_.kind == Kind::Arrow) {
            take();
            r.alternatives.push_back(application());
            while (tok_.is(',')) {
                take();
                if (tok_.is(';')) break;  // a trailing comma, as §3.7.4 writes it
                r.alternatives.push_back(application());
            }
        } else {
            expected("'->' (or '→') or '=' after the handle " + shortened(r.predecessor));
        }
        endStatement("to end the rule");
        f.rules.push_back(std::move(r));
    }

    const std::string& text_;
    std::string path_;
    std::size_t pos_ = 0;
    int line_ = 1, column_ = 1;
    int endLine_ = 1, endColumn_ = 1;  ///< just past the last token taken
    Token tok_;
    bool bare_ = false;  ///< the last application ended with a bare successor (no braces)
    Token bareHandle_;
    Location bareEnd_;   ///< just past the token before it
};

}  // namespace

File readCrl(const std::string& text, const std::string& path) { return Reader(text, path).run(); }

}  // namespace shapevo::crl
