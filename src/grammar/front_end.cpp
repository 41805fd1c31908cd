// Grammar front ends: which reader a grammar file goes to (by extension), and the CastleMaker
// front end's last step: its translation (crl/) is parsed as .grammar text, and any problem that
// parse finds is reported at the rule-file place the offending line came from.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/input_error.hpp"
#include "grammar/crl/crl_translator.hpp"
#include "grammar/parser.hpp"

namespace shapevo {

bool isRuleFile(const std::string& path) { return std::filesystem::path(path).extension() == ".rule"; }

namespace {
/// The grammar of rule file `path` (its `text`) from its translation `t`.
Grammar compileTranslation(const crl::Translation& t, const std::string& text, const std::string& path, const AttrOverrides& overrides) {
    try {
        Grammar g = parseShapeGrammar(t.text, path, overrides);
        g.source = text;
        g.includes = t.files;
        return g;
    } catch (const InputError& e) {
        const std::string& where = e.where();
        const std::size_t colon = where.find(':');
        if (e.file() != path || colon == std::string::npos) throw;
        const long line = std::strtol(where.c_str(), nullptr, 10);
        if (line < 1 || std::size_t(line) > t.origin.size()) throw;
        std::istringstream lines(t.text);
        std::string generated;
        for (long k = 0; k < line; ++k) std::getline(lines, generated);
        const crl::Location& from = t.origin[std::size_t(line - 1)];
        throw InputError(from.file, std::to_string(from.line) + ":" + std::to_string(from.column),
                         e.message() + " (in its translation to the shapevo language: " + shortened(generated, 160) + ")");
    }
}
}  // namespace

std::string translateRuleFile(const std::string& path, const AttrOverrides& overrides) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "", "cannot open rule file");
    std::ostringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    const crl::Translation t = crl::translateCrl(text, path, overrides);
    compileTranslation(t, text, path, overrides);  // the same checks as every command
    std::istringstream lines(t.text);
    std::string out = "# " + path + " in the shapevo language (grammars/README.md); # FILE:LINE says where a rule came from\n";
    std::string line, last;
    for (std::size_t k = 0; std::getline(lines, line); ++k) {
        const crl::Location& from = t.origin[k];
        std::string place = std::filesystem::path(from.file).filename().string() + ":" + std::to_string(from.line);
        out += line;
        if (place != last && line.rfind("rule ", 0) == 0) out += "    # " + place;
        if (line.rfind("rule ", 0) == 0) last = place;
        out += "\n";
    }
    return out;
}

Grammar parseGrammar(const std::string& text, const std::string& path, const AttrOverrides& overrides) {
    if (!isRuleFile(path)) return parseShapeGrammar(text, path, overrides);
    return compileTranslation(crl::translateCrl(text, path, overrides), text, path, overrides);
}

Grammar loadGrammar(const std::string& path, const AttrOverrides& overrides) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path, "", "is a directory, not a grammar file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "", isRuleFile(path) ? "cannot open rule file" : "cannot open grammar file");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw InputError(path, "", "cannot read grammar file");
    return parseGrammar(ss.str(), path, overrides);
}

}  // namespace shapevo
