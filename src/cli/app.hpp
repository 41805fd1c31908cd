// The command line's parser: the CLI11 app with one subcommand per entry of commands() (in table
// order, each with the options its addOptions declares). main.cpp parses with it; the reference
// pages (cli/reference_pages.hpp) are written from it, so --help, docs/reference/commands.md and
// the man page say the same.
#pragma once
#include <memory>

#include <CLI/CLI.hpp>

namespace shapevo {

/// The app; its subcommands are in the order of commands(). Options bind to storage the command
/// files own, so build one app per process run (a second one rebinds the same storage).
std::unique_ptr<CLI::App> makeApp();

/// shapevo's version, as --version prints it.
inline constexpr const char* kVersion = "0.1.0";

}  // namespace shapevo
