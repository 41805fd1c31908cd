// `shapevo translate FILE`: print what a grammar file of a front end that translates (a CastleMaker
// rule file today; grammar/front_ends.hpp) compiles into, in the shapevo grammar language.
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "base/input_error.hpp"
#include "cli/commands.hpp"
#include "grammar/front_ends.hpp"
#include "run/command_options.hpp"

namespace shapevo {

namespace {

struct TranslateOptions {
    std::string path;
    std::vector<std::string> attrs;
};
TranslateOptions translateOptions;

}  // namespace

void TranslateCommand::addOptions(CLI::App& command) {
    TranslateOptions& o = translateOptions;
    command.add_option("file", o.path, "grammar file to translate: " + translatingFrontEnds() + " (grammars/castlemaker/README.md)")
        ->required();
    command.add_option("--attr", o.attrs, "replace an attr of the file, NAME=VALUE (repeatable)");
}

void TranslateCommand::run(const CommandContext&) {
    const TranslateOptions& o = translateOptions;
    std::cout << translateGrammarFile(o.path, parseAttrOptions(o.attrs));
}

}  // namespace shapevo
