// The command line's parser (app.hpp).
#include "cli/app.hpp"

#include <string>

#include "cli/commands.hpp"

namespace shapevo {

std::unique_ptr<CLI::App> makeApp() {
    auto app = std::make_unique<CLI::App>(
        "shapevo: evolve procedural models (grammars) until they match a target: a volume to fill or a picture to cover.\n"
        "Guide: docs/README.md; grammar language: grammars/README.md; every option: shapevo COMMAND --help",
        "shapevo");
    app->require_subcommand(1);
    app->set_version_flag("--version", std::string("shapevo ") + kVersion);
    for (const CommandEntry& c : commands()) c.addOptions(*app->add_subcommand(std::string(c.name), std::string(c.summary)));
    return app;
}

}  // namespace shapevo
