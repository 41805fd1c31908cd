// scratchFolder: a fuzz target's own temporary folder (under $TMPDIR, which .ci/fuzz points into
// its work folder), made once per process and removed at exit, for readers that take a path.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <unistd.h>

namespace shapevo::fuzz {

/// Makes the folder `$TMPDIR/<prefix>.XXXXXX` (aborting if it cannot) and returns its path.
inline const std::string& scratchFolder(const char* prefix) {
    // Never destroyed: the exit handler below runs after function-local statics are gone.
    static const std::string* const folder = [prefix] {
        const char* tmp = std::getenv("TMPDIR");
        auto* name = new std::string(std::string(tmp && *tmp ? tmp : "/tmp") + "/" + prefix + ".XXXXXX");
        if (!mkdtemp(name->data())) {
            std::perror("mkdtemp");
            std::abort();
        }
        return name;
    }();
    static const bool removeAtExit = [] {
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(*folder, ec);
        });
        return true;
    }();
    (void)removeAtExit;
    return *folder;
}

}  // namespace shapevo::fuzz
