// The table of grammar front ends, reading a grammar file, and dispatching by extension.
#include "grammar/front_ends.hpp"

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "base/input_error.hpp"
#include "base/word_list.hpp"
#include "grammar/crl/crl_translator.hpp"
#include "grammar/grammar_diagram.hpp"
#include "grammar/parser.hpp"
#include "grammar/pcg/pcg_front_end.hpp"

namespace shapevo {

namespace {

Grammar compileShapeGrammar(const std::string& text, const std::string& path, const AttrOverrides& overrides) {
    return parseShapeGrammar(text, path, overrides);
}

Translation translateRuleFile(const std::string& text, const std::string& path, const AttrOverrides& overrides) {
    return crl::translateCrl(text, path, overrides);
}
Grammar compileRuleFile(const std::string& text, const std::string& path, const AttrOverrides& overrides) {
    return compileTranslation(crl::translateCrl(text, path, overrides), text, path, overrides);
}

Translation translateGraphFile(const std::string& text, const std::string& path, const AttrOverrides&) {
    return pcg::translatePcg(text, path);  // attrs stay attrs: the shapevo parser applies the overrides
}
Grammar compileGraphFile(const std::string& text, const std::string& path, const AttrOverrides& overrides) {
    return compileTranslation(pcg::translatePcg(text, path), text, path, overrides);
}
pcg::GraphDiagram graphFileDiagram(const std::string& text, const std::string& path, const AttrOverrides&) {
    return pcg::pcgDiagram(text, path);
}

constexpr std::array<GrammarFrontEnd, 3> kFrontEnds{{
    {".grammar", "shapevo grammar", "the shapevo grammar language (grammars/README.md)", "grammar file",
     compileShapeGrammar, nullptr, false},
    {".rule", "CastleMaker rule file", "CastleMaker's CRL, translated into the shapevo language (grammars/castlemaker/README.md)",
     "rule file", compileRuleFile, translateRuleFile, true},
    {".pcg", "procedural content graph", "a node graph (PCGR), translated into the shapevo language (grammars/pcg/README.md)",
     "graph file", compileGraphFile, translateGraphFile, false, graphFileDiagram},
}};

/// The whole text of `path`, read for front end `fe`.
std::string readGrammarFile(const std::string& path, const GrammarFrontEnd& fe) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path, "", "is a directory, not a grammar file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "", "cannot open " + std::string(fe.fileNoun));
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw InputError(path, "", "cannot read grammar file");
    return ss.str();
}

}  // namespace

std::span<const GrammarFrontEnd> grammarFrontEnds() { return kFrontEnds; }

const GrammarFrontEnd* findGrammarFrontEnd(std::string_view extension) {
    for (const GrammarFrontEnd& e : kFrontEnds)
        if (e.extension == extension) return &e;
    return nullptr;
}

const GrammarFrontEnd& grammarFrontEndFor(const std::string& path) {
    const GrammarFrontEnd* e = findGrammarFrontEnd(std::filesystem::path(path).extension().string());
    return e ? *e : kFrontEnds.front();
}

std::string grammarExtensions() {
    return wordList(kFrontEnds.size(), [](std::size_t i) { return "\"" + std::string(kFrontEnds[i].extension) + "\""; });
}

std::string translatingFrontEnds() {
    std::vector<const GrammarFrontEnd*> those;
    for (const GrammarFrontEnd& e : kFrontEnds)
        if (e.translate) those.push_back(&e);
    return wordList(those.size(), [&](std::size_t i) {
        return "a " + std::string(those[i]->name) + " (" + std::string(those[i]->extension) + ")";
    });
}

Grammar parseGrammar(const std::string& text, const std::string& path, const AttrOverrides& overrides) {
    return grammarFrontEndFor(path).compile(text, path, overrides);
}

Grammar loadGrammar(const std::string& path, const AttrOverrides& overrides) {
    const GrammarFrontEnd& fe = grammarFrontEndFor(path);
    return fe.compile(readGrammarFile(path, fe), path, overrides);
}

pcg::GraphDiagram grammarFileDiagram(const std::string& path, const AttrOverrides& overrides) {
    const std::string extension = std::filesystem::path(path).extension().string();
    const GrammarFrontEnd* fe = findGrammarFrontEnd(extension);
    if (!fe) {
        const std::string what =
            extension.empty() ? "has no file extension" : "unknown grammar file extension '" + shortened(extension) + "'";
        throw InputError(path, "", what + "; shapevo graph reads " + grammarExtensions() + " files");
    }
    const std::string text = readGrammarFile(path, *fe);
    return fe->diagram ? fe->diagram(text, path, overrides) : grammarDiagram(fe->compile(text, path, overrides));
}

std::string translateGrammarFile(const std::string& path, const AttrOverrides& overrides) {
    const GrammarFrontEnd& fe = grammarFrontEndFor(path);
    if (!fe.translate)
        throw InputError(path, "", "is read as a " + std::string(fe.name) + ", which needs no translation; shapevo translate reads " +
                                       translatingFrontEnds());
    const std::string text = readGrammarFile(path, fe);
    const Translation t = fe.translate(text, path, overrides);
    compileTranslation(t, text, path, overrides);  // the same checks as every command
    return translationListing(t, path);
}

}  // namespace shapevo
