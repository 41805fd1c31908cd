// writeAtomically: temporary file in the destination's directory, fsync, rename.
#include "io/atomic_write.hpp"

#include <atomic>
#include <filesystem>
#include <fstream>

#include <fcntl.h>
#include <unistd.h>

#include "io/input_error.hpp"

namespace shapevo {

namespace fs = std::filesystem;

namespace {

std::string temporaryPath(const fs::path& out) {
    static std::atomic<unsigned> counter{0};
    const std::string name = "." + out.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                             std::to_string(counter++);
    return (out.parent_path() / name).string();
}

/// Flushes a file (or directory) to disk so that the rename that follows cannot publish lost data.
void syncPath(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

}  // namespace

void writeAtomically(const std::string& path, const std::function<void(const std::string& tempPath)>& write) {
    const std::string temp = temporaryPath(fs::path(path));
    std::error_code ec;
    try {
        write(temp);
    } catch (...) {
        fs::remove(temp, ec);
        throw;
    }
    if (!fs::is_regular_file(temp, ec)) throw InputError(path, "", "cannot write: the file was not created");
    syncPath(temp);
    fs::rename(temp, path, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw InputError(path, "", "cannot write: " + ec.message());
    }
    const fs::path dir = fs::path(path).parent_path();
    syncPath(dir.empty() ? "." : dir.string());
}

void writeStreamAtomically(const std::string& path, const std::function<void(std::ostream& out)>& write) {
    writeAtomically(path, [&](const std::string& temp) {
        std::ofstream out(temp, std::ios::binary);
        if (!out) throw InputError(path, "", "cannot write: cannot create a file in its folder");
        write(out);
        out.close();
        if (!out) throw InputError(path, "", "cannot write: output error (disk full?)");
    });
}

}  // namespace shapevo
