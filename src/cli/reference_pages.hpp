// The reference pages written from the code: docs/reference/commands.md (every command's --help,
// as the binary prints it), docs/reference/config.md (run/config_reference.hpp) and the man page
// shapevo.1 (commands, options, config keys, exit codes) — `shapevo reference` prints or writes
// them, and a test fails when docs/reference/ differs from what it writes.
#pragma once
#include <string>

#include <CLI/CLI.hpp>

namespace shapevo {

/// Markdown: the program's --help, then each command's --help in a text block.
std::string commandsMarkdown(const CLI::App& app);

/// A man page (roff, man(7) macros) of the program: its commands with their options, the config
/// keys by section, exit codes and files.
std::string manPage(const CLI::App& app);

}  // namespace shapevo
