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
    static const std::string folder = [prefix] {
        const char* tmp = std::getenv("TMPDIR");
        std::string name = std::string(tmp && *tmp ? tmp : "/tmp") + "/" + prefix + ".XXXXXX";
        if (!mkdtemp(name.data())) {
            std::perror("mkdtemp");
            std::abort();
        }
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(scratchFolder(""), ec);
        });
        return name;
    }();
    return folder;
}

}  // namespace shapevo::fuzz
