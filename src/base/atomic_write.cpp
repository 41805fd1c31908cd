// writeAtomically: temporary file in the destination's directory, fsync, rename, fsync of the folder.
#include "base/atomic_write.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

#include "base/input_error.hpp"

namespace shapevo {

namespace fs = std::filesystem;

namespace {

std::string temporaryPath(const fs::path& out) {
    static std::atomic<unsigned> counter{0};
    std::string name(1, '.');  // built step by step: GCC 12 warns (-Wrestrict) on "." + string
    name += out.filename().string();
    name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    return (out.parent_path() / name).string();
}

}  // namespace

void syncToDisk(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw std::runtime_error(path + ": cannot open to flush to disk: " + std::strerror(errno));
    const int rc = ::fsync(fd);
    const int err = errno;
    ::close(fd);
    if (rc != 0 && err != EINVAL) throw std::runtime_error(path + ": cannot flush to disk: " + std::strerror(err));
}

namespace {

/// Gives `temp` the name `path` without replacing an existing file; false (and `temp` kept)
/// where the file system has no hard links.
bool linkIntoPlace(const std::string& temp, const std::string& path) {
    std::error_code ec;
    if (::link(temp.c_str(), path.c_str()) == 0) {
        fs::remove(temp, ec);
        return true;
    }
    const int err = errno;
    if (err == EEXIST || fs::exists(path, ec)) {
        fs::remove(temp, ec);
        throw InputError(path, "", "already exists; refusing to overwrite it");
    }
    return false;  // no hard links here: check-then-rename below (a tiny race, but no torn file)
}

}  // namespace

void writeAtomically(const std::string& path, const std::function<void(const std::string& tempPath)>& write,
                     Replace replace) {
    const std::string temp = temporaryPath(fs::path(path));
    std::error_code ec;
    try {
        write(temp);
    } catch (...) {
        fs::remove(temp, ec);
        throw;
    }
    if (!fs::is_regular_file(temp, ec)) throw InputError(path, "", "cannot write: the file was not created");
    try {
        syncToDisk(temp);
    } catch (...) {
        fs::remove(temp, ec);
        throw;
    }
    if (replace == Replace::Never && linkIntoPlace(temp, path)) {
        const fs::path dir = fs::path(path).parent_path();
        syncToDisk(dir.empty() ? "." : dir.string());
        return;
    }
    fs::rename(temp, path, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw InputError(path, "", "cannot write: " + ec.message());
    }
    const fs::path dir = fs::path(path).parent_path();
    syncToDisk(dir.empty() ? "." : dir.string());
}

void writeStreamAtomically(const std::string& path, const std::function<void(std::ostream& out)>& write,
                           Replace replace) {
    const auto writeStream = [&](const std::string& temp) {
        std::ofstream out(temp, std::ios::binary);
        if (!out) throw InputError(path, "", "cannot write: cannot create a file in its folder");
        write(out);
        out.close();
        if (!out) throw InputError(path, "", "cannot write: output error (disk full?)");
    };
    writeAtomically(path, writeStream, replace);
}

}  // namespace shapevo
