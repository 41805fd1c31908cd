// CRL translator (internal to src/grammar/crl/): turns rule files into the text of a .grammar
// file that derives the same models, and remembers which rule-file place each line came from.
//
// The one place CastleMaker's z-up world meets shapevo's y-up world: a CRL point (x, y, z) is
// shapevo's (x, z, -y). A CRL component (a transformation of the unit box (-0.5, -0.5, 0) to
// (0.5, 0.5, 1), §3.6.3-3.6.4) is a shapevo scope whose x axis is the component's X, whose y axis
// its Z (up) and whose z axis its -Y; the scope's centre is the box's centre, so the component's
// base is at -size.y / 2. Every CRL function is a few scope statements on that frame (the table
// in grammars/castlemaker/README.md), so the thesis's matrices hold: extrude(h) and scale(...)
// multiply sizes about the base centre, translate(...) moves by fractions of the sizes, rect and
// circ make frames of height 1.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "grammar/crl/crl_syntax.hpp"
#include "grammar/translation.hpp"

namespace shapevo::crl {

/// Translate the rule file `path` (its text given) into the shapevo language (grammar/translation.hpp;
/// Translation::files: every included or inserted rule file read). `attrs` replaces attrs' values as a config's
/// [grammar.attr] does (the translation needs them where a count shapes the model).
/// @throw InputError at file:line:column for every problem the rule file has.
Translation translateCrl(const std::string& text, const std::string& path, const std::map<std::string, double>& attrs);

/// `v` as the translation writes it (9 significant digits; a negative number in parentheses, so
/// that it can stand anywhere in an expression).
std::string number(double v);
/// `v` as a message shows it (9 significant digits, no parentheses).
std::string shown(double v);

/// Argument types of CRL functions.
enum class ArgType { Real, Int, Bool, String };

/// One translated argument: a .grammar expression, and its value when it is a constant.
struct Value {
    std::string expr;
    bool constant = false;
    double value = 0;
    std::string text;  ///< String arguments
    Location where;
};

class Translator;

/// What a function's emitter sees (crl_functions.cpp).
struct Call {
    Translator& t;
    const Application& app;
    std::vector<Value> args;
    std::vector<std::string> successors;  ///< rule names to call inline, in order
    bool inLot = false;                   ///< a direct lot: the frame is the start rule's
    void line(const std::string& s);      ///< one statement line at the application's place
    const std::string& succ(std::size_t k) const { return successors[k % successors.size()]; }
    [[noreturn]] void fail(const Location& at, const std::string& what) const;
};

/// A CRL function: its name, argument types (a variadic tail repeats the last type), how many
/// successors it takes, and its emitter.
struct Function {
    const char* name;
    std::vector<ArgType> args;
    int optionalArgs;      ///< how many of the trailing args may be left out
    bool variadic;         ///< the last type repeats (at least once)
    int minSuccessors, maxSuccessors;  ///< maxSuccessors -1: any number
    void (*emit)(Call&);
};
const Function* findFunction(const std::string& name);

// What emitters ask of the translator (crl_translate.cpp).
/// Declares `param NAME = PRIOR per piece` at the current place; returns NAME.
std::string declareParam(Translator& t, const std::string& prior);
/// `file` (relative to the folder of the rule file being read) as a path relative to the main
/// file's folder; it must exist. `what` names it in the message ("texture", "OBJ").
std::string fileFor(Translator& t, const Location& at, const std::string& file, const char* what);
/// The height (z extent) of an OBJ in its own units (insert's not_scale_z).
double objectHeight(Translator& t, const Location& at, const std::string& mainRelative);
/// The rule that draws an inserted rule file's model into the current frame (§6.2).
std::string insertedModel(Translator& t, const Location& at, const std::string& mainRelative, bool textured, bool local);
/// How this translation treats add_material / add_texture: Keep, Drop (an inserted model whose
/// insert says is_textured = 0: the parent's look applies) or the material's name to use.
enum class Looks { Keep, Drop };
Looks looks(const Translator& t);
/// A generated rule (named crl__h<N>) whose body `body` writes with Call::line / declareParam;
/// made once per `key` and translation unit, so every piece that calls it shares its statements.
std::string helperRule(Translator& t, const std::string& key, const std::function<void()>& body);
/// The material name to write for `name` (an inserted model's own materials are kept apart
/// unless its insert says keep_materials_local).
std::string materialName(const Translator& t, const std::string& name);
/// Every function's name, for messages.
std::string functionNames();
/// The function whose name is nearest to a misspelt `name` (at most two edits), or "".
std::string similarFunction(const std::string& name);

}  // namespace shapevo::crl
