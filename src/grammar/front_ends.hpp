// The grammar front ends: one table, one entry per kind of grammar file — `.grammar` (the shapevo
// language), `.rule` (CastleMaker's CRL, grammar/crl/) and `.pcg` (procedural content graphs,
// grammar/pcg/) — each with its extension, its name, a one-line summary, how it compiles a file
// into the Grammar, how it translates one into the shapevo language if it does, what a derivation
// of it may do, and what `shapevo graph` draws of it. Every command that takes a grammar (`run`,
// `resume`, `evaluate`, `export`, `render`, `inspect`, `sample`, `translate`, `graph`) and --help
// read this table, so a new front end is its folder plus one entry in front_ends.cpp. Every front
// end reports a problem at file:line:column of the user's own file (InputError), and lists the
// other files it reads (Grammar::includes), which a run hashes so `resume` refuses a changed one.
// (2D graph grammars, .yml / .yaml, are another model family: graph/read_graph_grammar.hpp.)
#pragma once
#include <span>
#include <string>
#include <string_view>

#include "grammar/attr_overrides.hpp"
#include "grammar/grammar.hpp"
#include "grammar/pcg/graph_diagram.hpp"
#include "grammar/translation.hpp"

namespace shapevo {

struct GrammarFrontEnd {
    std::string_view extension;  ///< with its dot: ".grammar"
    std::string_view name;       ///< for messages and --help: "CastleMaker rule file"
    std::string_view summary;    ///< one line for --help and messages
    std::string_view fileNoun;   ///< what "cannot open ..." calls one file: "grammar file", "rule file"
    /// The checked Grammar of the file `path` whose text is `text`. @throw InputError
    Grammar (*compile)(const std::string& text, const std::string& path, const AttrOverrides& overrides);
    /// Its text in the shapevo language and where each line came from (what `shapevo translate`
    /// prints); nullptr for the shapevo language itself. @throw InputError
    Translation (*translate)(const std::string& text, const std::string& path, const AttrOverrides& overrides);
    /// Its recursions may end only by chance (a CastleMaker recursive stochastic rule,
    /// castlemaker-crl.txt §5.2), so an uncontrolled derivation may grow without end whatever
    /// hasOptionalRecursion (genome/sample.hpp) finds in the compiled Grammar.
    bool recursionsEndOnlyByChance = false;
    /// Its own picture for `shapevo graph` (a graph file's nodes and ports); nullptr: the
    /// generator graph of the compiled Grammar (grammar/grammar_diagram.hpp). @throw InputError
    pcg::GraphDiagram (*diagram)(const std::string& text, const std::string& path, const AttrOverrides& overrides) = nullptr;
};

/// Every front end, the shapevo language first.
std::span<const GrammarFrontEnd> grammarFrontEnds();

/// The entry whose extension is `extension` (with its dot), or nullptr.
const GrammarFrontEnd* findGrammarFrontEnd(std::string_view extension);

/// The front end that reads `path`: by its extension; any extension no entry names (".txt", none)
/// is read as the shapevo language, as it always was (configs and checkpoints may name such files).
const GrammarFrontEnd& grammarFrontEndFor(const std::string& path);

/// The extensions for a message: "\".grammar\" or \".rule\"".
std::string grammarExtensions();

/// The front ends that translate, for messages and --help: "a CastleMaker rule file (.rule)".
std::string translatingFrontEnds();

/// Parse grammar text with the front end its path's extension names (grammarFrontEndFor).
Grammar parseGrammar(const std::string& text, const std::string& path, const AttrOverrides& overrides = {});
/// Read and parse a grammar file of any front end.
Grammar loadGrammar(const std::string& path, const AttrOverrides& overrides = {});

/// What `shapevo graph` draws for grammar file `path`: its front end's own picture, or else the
/// generator graph of the Grammar it compiles into (grammar/grammar_diagram.hpp).
/// @throw InputError for an extension no front end names (unlike loadGrammar, no default); any problem of the file.
pcg::GraphDiagram grammarFileDiagram(const std::string& path, const AttrOverrides& overrides = {});

/// The shapevo-language text a file of a translating front end compiles into, as `shapevo
/// translate` prints it, after the same checks loadGrammar makes.
/// @throw InputError naming the front ends that translate if `path`'s does not; any problem of the file.
std::string translateGrammarFile(const std::string& path, const AttrOverrides& overrides = {});

}  // namespace shapevo
