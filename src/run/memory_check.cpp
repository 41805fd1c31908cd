// Memory check: estimate x islands vs. the usable memory.
#include "run/memory_check.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

#include "base/input_error.hpp"
#include "search/memory_estimate.hpp"

namespace shapevo {

namespace {

/// The number in the first line of `path`, or 0 ("max", missing, unreadable).
std::uint64_t limitFromFile(const char* path) {
    std::ifstream in(path);
    std::string line;
    if (!in || !std::getline(in, line) || line.empty() || line.find_first_not_of("0123456789") != std::string::npos)
        return 0;
    try {
        return std::stoull(line);
    } catch (const std::exception&) {
        return 0;
    }
}

std::string gib(double bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
    return buf;
}

}  // namespace

std::uint64_t usableMemoryBytes() {
    std::uint64_t usable = 0;
    auto lower = [&](std::uint64_t limit) {
        if (limit > 0 && (usable == 0 || limit < usable)) usable = limit;
    };
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
    if (pages > 0 && pageSize > 0) lower(std::uint64_t(pages) * std::uint64_t(pageSize));
    lower(limitFromFile("/sys/fs/cgroup/memory.max"));
    {  // this process's own group: "0::/path" (v2) or "N:memory:/path" (v1) in /proc/self/cgroup
        std::ifstream in("/proc/self/cgroup");
        for (std::string line; std::getline(in, line);) {
            if (line.rfind("0::/", 0) == 0 && line.size() > 4)
                lower(limitFromFile(("/sys/fs/cgroup" + line.substr(3) + "/memory.max").c_str()));
            if (const auto m = line.find(":memory:/"); m != std::string::npos && line.size() > m + 9)
                lower(limitFromFile(("/sys/fs/cgroup/memory" + line.substr(m + 8) + "/memory.limit_in_bytes").c_str()));
        }
    }
    lower(limitFromFile("/sys/fs/cgroup/memory/memory.limit_in_bytes"));
    rlimit as{};
    if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) lower(std::uint64_t(as.rlim_cur));
    return usable;
}

void requireMemoryFits(const RunSettings& s, const GenomeFamily& family, int islands, std::uint64_t available) {
    if (available == 0) return;
    const MemoryEstimate e = searchMemoryEstimate(family, s.search, s.population, s.limits);
    const double need = e.bytes * double(std::max(islands, 1));
    if (need <= double(available)) return;
    throw InputError(s.configPath, "ga.population",
                     "ga.population = " + std::to_string(s.population.population) + " with genome.max_genes = " +
                         std::to_string(s.limits.maxGenes) + " may need " + gib(need) + " (" + e.formula +
                         (islands > 1 ? ", x " + std::to_string(islands) + " islands on this machine" : "") + "), more than the " +
                         gib(double(available)) + " this process may use (physical memory, or a lower cgroup or ulimit limit); lower ga.population or genome.max_genes");
}

}  // namespace shapevo
