// `shapevo translate FILE.rule`: print what a CastleMaker rule file compiles into, in the shapevo
// grammar language (grammar/parser.hpp).
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "base/input_error.hpp"
#include "cli/commands.hpp"
#include "grammar/parser.hpp"
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
    command.add_option("rule_file", o.path, "CastleMaker rule file (grammars/castlemaker/README.md)")->required();
    command.add_option("--attr", o.attrs, "replace an attr of the rule file, NAME=VALUE (repeatable)");
}

void TranslateCommand::run(const CommandContext&) {
    const TranslateOptions& o = translateOptions;
    if (!isRuleFile(o.path)) throw InputError(o.path, "", "not a CastleMaker rule file (expected a .rule file)");
    std::cout << translateRuleFile(o.path, parseAttrOptions(o.attrs));
}

}  // namespace shapevo
