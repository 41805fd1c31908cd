// RunFolderLock: flock on RUN_DIR/.lock, holder "host pid" written into it.
#include "run/run_folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

#include "base/input_error.hpp"

namespace shapevo {

RunFolderLock::RunFolderLock(const std::string& runDir) {
    const std::string path = runDir + "/.lock";
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw InputError(runDir, "", std::string("cannot create its lock file .lock: ") + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int err = errno;
        char holder[256] = {0};
        const ssize_t n = ::pread(fd_, holder, sizeof holder - 1, 0);
        std::string who = n > 0 ? std::string(holder, std::size_t(n)) : std::string();
        while (!who.empty() && (who.back() == '\n' || who.back() == '\0')) who.pop_back();
        ::close(fd_);
        fd_ = -1;
        if (err == EWOULDBLOCK)
            throw InputError(runDir, "", "is in use by another shapevo (" + (who.empty() ? "holder unknown" : who) +
                                             "); only one run or resume may write a run folder at a time");
        throw InputError(runDir, "", std::string("cannot lock its lock file .lock: ") + std::strerror(err));
    }
    char host[256] = {0};
    ::gethostname(host, sizeof host - 1);
    const std::string who = std::string("host ") + host + ", pid " + std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd_, 0) == 0) {
        const ssize_t ignored = ::pwrite(fd_, who.data(), who.size(), 0);
        (void)ignored;  // the holder's name is a courtesy; the lock itself is what counts
    }
}

RunFolderLock::RunFolderLock(RunFolderLock&& o) noexcept : fd_(std::exchange(o.fd_, -1)) {}

RunFolderLock& RunFolderLock::operator=(RunFolderLock&& o) noexcept {
    if (this != &o) {
        if (fd_ >= 0) ::close(fd_);
        fd_ = std::exchange(o.fd_, -1);
    }
    return *this;
}

RunFolderLock::~RunFolderLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the flock
}

}  // namespace shapevo
