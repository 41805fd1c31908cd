// Compiling a translation (its text through the shapevo parser, its problems moved back to the
// user's file) and listing one for `shapevo translate`.
#include "grammar/translation.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "base/input_error.hpp"
#include "grammar/parser.hpp"

namespace shapevo {

Grammar compileTranslation(const Translation& t, const std::string& source, const std::string& path, const AttrOverrides& overrides) {
    try {
        Grammar g = parseShapeGrammar(t.text, path, overrides);
        g.source = source;
        g.includes = t.files;
        return g;
    } catch (const InputError& e) {
        const std::string& where = e.where();
        const std::size_t colon = where.find(':');
        if (e.file() != path || colon == std::string::npos) throw;
        const long line = std::strtol(where.c_str(), nullptr, 10);
        if (line < 1 || t.origin.empty()) throw;
        // past the translation's last line (its end of file, e.g. a brace an argument left open):
        // the place its last line came from, never the translation's own line number
        const bool pastEnd = std::size_t(line) > t.origin.size();
        std::istringstream lines(t.text);
        std::string generated;
        for (long k = 0; k < line && std::getline(lines, generated); ++k) {
        }
        if (pastEnd) generated = "its end";
        const Location& from = t.origin[std::min(std::size_t(line), t.origin.size()) - 1];
        throw InputError(from.file, std::to_string(from.line) + ":" + std::to_string(from.column),
                         e.message() + " (in its translation to the shapevo language: " + shortened(generated, 160) + ")");
    }
}

std::string translationListing(const Translation& t, const std::string& path) {
    std::istringstream lines(t.text);
    std::string out = "# " + path + " in the shapevo language (grammars/README.md); # FILE:LINE says where a rule came from\n";
    std::string line, last;
    for (std::size_t k = 0; std::getline(lines, line); ++k) {
        const Location& from = t.origin[k];
        std::string place = std::filesystem::path(from.file).filename().string() + ":" + std::to_string(from.line);
        out += line;
        if (place != last && line.rfind("rule ", 0) == 0) out += "    # " + place;
        if (line.rfind("rule ", 0) == 0) last = place;
        out += "\n";
    }
    return out;
}

}  // namespace shapevo
