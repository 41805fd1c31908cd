// InputError: the one exception type for bad user input (grammar, config, mesh, VDB, PNG).
// It names the file and the place inside it; the CLI prints what() and exits with code 2.
#pragma once
#include <stdexcept>
#include <string>

namespace shapevo {

class InputError : public std::runtime_error {
public:
    /// @param file  path of the offending file (or a description such as "--set")
    /// @param where place inside it, e.g. "12:5" or "[ga] population"; may be empty
    /// @param what  what was wrong and, where it helps, what was expected
    InputError(const std::string& file, const std::string& where, const std::string& what)
        : std::runtime_error(file + (where.empty() ? "" : ":" + where) + ": " + what),
          file_(file), where_(where) {}
    const std::string& file() const { return file_; }
    const std::string& where() const { return where_; }

private:
    std::string file_, where_;
};

}  // namespace shapevo
