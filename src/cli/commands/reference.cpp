// `shapevo reference [config|commands|man]`: print a reference page written from the code
// (cli/reference_pages.hpp); `--write DIR` writes all three into DIR (docs/reference/ in the
// source: config.md, commands.md, shapevo.1), each file whole or not at all.
#include <filesystem>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "base/atomic_write.hpp"
#include "base/input_error.hpp"
#include "cli/app.hpp"
#include "cli/commands.hpp"
#include "cli/reference_pages.hpp"
#include "run/config_reference.hpp"

namespace shapevo {

namespace {

struct ReferenceOptions {
    std::string page;
    std::string writeTo;
};
ReferenceOptions referenceOptions;

struct Page {
    const char* name;  ///< what the positional names
    const char* file;  ///< its file under --write
    std::string (*make)(const CLI::App& app);
};
std::string configPage(const CLI::App&) { return configReferenceMarkdown(); }
constexpr Page kPages[] = {
    {"config", "config.md", configPage},
    {"commands", "commands.md", commandsMarkdown},
    {"man", "shapevo.1", manPage},
};

}  // namespace

void ReferenceCommand::addOptions(CLI::App& command) {
    ReferenceOptions& o = referenceOptions;
    command.add_option("page", o.page,
                       "the page to print: config (every config key: type, default, range, meaning; markdown), commands "
                       "(every command's --help; markdown) or man (the man page, roff)")
        ->check(CLI::IsMember({"config", "commands", "man"}));
    command.add_option("--write", o.writeTo,
                       "write all three pages into this folder (config.md, commands.md, shapevo.1), replacing them; "
                       "docs/reference is where the source keeps them")
        ->type_name("DIR");
}

void ReferenceCommand::run(const CommandContext&) {
    const ReferenceOptions& o = referenceOptions;
    if (o.page.empty() == o.writeTo.empty())
        throw InputError("shapevo reference", "", "name one page (config, commands or man) or give --write DIR, not both");
    const std::unique_ptr<CLI::App> app = makeApp();  // a fresh parser: its help as a user sees it
    for (const Page& p : kPages) {
        if (o.page == p.name) {
            std::cout << p.make(*app);
            return;
        }
    }
    std::error_code ec;
    if (!std::filesystem::is_directory(o.writeTo, ec)) throw InputError(o.writeTo, "", "is not a folder (--write needs one that exists)");
    for (const Page& p : kPages) {
        const std::string path = (std::filesystem::path(o.writeTo) / p.file).string();
        const std::string text = p.make(*app);
        writeStreamAtomically(path, [&](std::ostream& out) { out << text; });
        std::cout << "wrote " << path << "\n";
    }
}

}  // namespace shapevo
