// Checkpoint folders inside a run folder: their names, finding the published ones newest first,
// publishing a finished `.checkpoint-NNNNNN.partial/` with one rename, and pruning old ones.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "checkpoint/checkpoint_file.hpp"
#include "checkpoint/run_identity.hpp"
#include "base/atomic_write.hpp"

namespace shapevo {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kPrefix = "checkpoint-";

/// The generation of a folder named checkpoint-NNNNNN (six to ten digits), or -1.
long long publishedGeneration(const std::string& name) {
    if (!name.starts_with(kPrefix)) return -1;
    const std::string digits = name.substr(kPrefix.size());
    if (digits.size() < 6 || digits.size() > 10) return -1;
    long long g = 0;
    for (char c : digits) {
        if (c < '0' || c > '9') return -1;
        g = g * 10 + (c - '0');
    }
    return g;
}

/// Unpublished leftovers: `.checkpoint-*.partial` (never finished) and `.checkpoint-*.replaced`
/// (a same-generation folder moved aside by publishCheckpoint, left by a crash).
bool isLeftover(const std::string& name) {
    return name.starts_with(".checkpoint-") && (name.ends_with(".partial") || name.ends_with(".replaced"));
}

}  // namespace

std::string checkpointName(std::uint32_t generation) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "checkpoint-%06u", unsigned(generation));
    return buf;
}

std::string islandFileName(int rank) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "island-%04d.h5", rank);
    return buf;
}

std::vector<std::string> listCheckpoints(const std::string& runDir) {
    std::vector<std::pair<long long, std::string>> found;
    std::error_code ec;
    for (fs::directory_iterator it(runDir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const long long g = publishedGeneration(name);
        std::error_code typeError;
        if (g >= 0 && it->is_directory(typeError)) found.emplace_back(g, it->path().string());
    }
    // Newest first; equal generations (checkpoint-000400 and checkpoint-0000400) by name.
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second > b.second;
    });
    std::vector<std::string> out;
    for (auto& f : found) out.push_back(std::move(f.second));
    return out;
}

void pruneCheckpoints(const std::string& runDir, int keep, const std::string& runId) {
    std::vector<std::string> ours;
    for (const std::string& c : listCheckpoints(runDir))
        if (checkpointRunId(c) == runId) ours.push_back(c);
    std::error_code ec;
    for (std::size_t i = std::size_t(std::max(keep, 1)); i < ours.size(); ++i) fs::remove_all(ours[i], ec);
    std::vector<fs::path> partial;
    for (fs::directory_iterator it(runDir, ec), end; !ec && it != end; it.increment(ec))
        if (isLeftover(it->path().filename().string())) partial.push_back(it->path());
    for (const fs::path& p : partial) fs::remove_all(p, ec);
}

void publishCheckpoint(const std::string& partialFolder, const std::string& finalFolder, const std::string& runId) {
    // The files were fsynced as they were written; fsync the folder so their names are durable too.
    syncToDisk(partialFolder);
    const fs::path final(finalFolder);
    const fs::path parent = final.parent_path().empty() ? fs::path(".") : final.parent_path();
    std::error_code ec;
    // A folder of the same generation exists when a run resumed from an older checkpoint because
    // this one was damaged (or when a deterministic resume repeats it): move it aside, publish,
    // then delete it. Older complete checkpoints stay throughout, so one is always there.
    std::string hidden = final.filename().string();
    hidden.insert(0, 1, '.');
    hidden += ".replaced";
    const fs::path displaced = parent / hidden;
    const bool replacing = fs::exists(final, ec);
    if (replacing) {
        const std::optional<std::string> owner = checkpointRunId(finalFolder);
        if (owner && *owner != runId)
            throw std::runtime_error(finalFolder + " is a checkpoint of another run (run id " + *owner +
                                     "); it is never replaced: move it out of this run folder");
        fs::remove_all(displaced, ec);
        fs::rename(final, displaced, ec);
        if (ec) throw std::runtime_error("cannot move " + finalFolder + " aside to publish a new one: " + ec.message());
    }
    fs::rename(partialFolder, final, ec);
    if (ec) throw std::runtime_error("cannot publish " + partialFolder + " as " + finalFolder + ": " + ec.message());
    syncToDisk(parent.string());
    if (replacing) fs::remove_all(displaced, ec);
}

}  // namespace shapevo
