// Run ids, the run folder's run-id file, island/run agreement and input hashes.
#include "checkpoint/run_identity.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>

#include "base/atomic_write.hpp"
#include "base/hash.hpp"
#include "base/input_error.hpp"
#include "checkpoint/checkpoint_file.hpp"

namespace shapevo {

namespace {

bool isRunId(const std::string& s) {
    if (s.size() != 32) return false;
    for (char c : s)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
    return true;
}

}  // namespace

std::string newRunId() {
    std::random_device device;
    std::string id;
    for (int i = 0; i < 4; ++i) {
        char b[9];
        std::snprintf(b, sizeof b, "%08x", static_cast<unsigned>(device()));
        id += b;
    }
    return id;
}

void writeRunId(const std::string& runDir, const std::string& runId) {
    writeStreamAtomically(runDir + "/" + kRunIdFile, [&](std::ostream& out) { out << runId << "\n"; });
}

std::string readRunId(const std::string& runDir) {
    const std::string path = runDir + "/" + kRunIdFile;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "", "missing: this folder was not made by a `shapevo run` of this version");
    std::string id;
    std::getline(in, id);
    if (!isRunId(id)) throw InputError(path, "line 1", "expected 32 lowercase hex digits (a run id)");
    return id;
}

std::optional<std::string> checkpointRunId(const std::string& checkpoint) {
    // run.h5 alone: this is asked of every kept checkpoint after each publish, and the island
    // files, which can be gigabytes, say nothing about whose checkpoint it is.
    if (!listedFileIsIntact(checkpoint, "run.h5")) return std::nullopt;
    try {
        return readRunMetadata(checkpoint + "/run.h5").runId;
    } catch (const InputError&) {
        return std::nullopt;
    }
}

std::string islandMismatch(const IslandState& island, const RunMetadata& run, int rank, bool ownPace) {
    auto differs = [](const char* what, const std::string& a, const std::string& b) {
        return std::string(what) + " is " + a + " in the island file but " + b + " in run.h5";
    };
    if (island.runId != run.runId) return differs("the run id", island.runId, run.runId);
    if (island.seed != run.seed) return differs("the seed", std::to_string(island.seed), std::to_string(run.seed));
    if (island.ranks != run.ranks) return differs("the island count", std::to_string(island.ranks), std::to_string(run.ranks));
    if (island.generation != run.generation && !ownPace)
        return differs("the generation", std::to_string(island.generation), std::to_string(run.generation));
    if (island.rank != rank) return "the file is island " + std::to_string(island.rank) + ", read by rank " + std::to_string(rank);
    return "";
}

InputFile hashInput(const std::string& role, const std::string& path) {
    const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
    const FileHash f = hashFile(absolute);
    if (!f.ok) throw InputError(path, "", "cannot read this " + role + " file");
    return {role, absolute, f.hash};
}

InputFile recordInput(const std::string& role, const std::string& path, std::uint64_t hash) {
    return {role, std::filesystem::absolute(path).lexically_normal().string(), hash};
}

std::vector<std::string> changedInputs(const std::vector<InputFile>& inputs) {
    std::vector<std::string> changed;
    for (const InputFile& f : inputs) {
        std::uint64_t now = 0;
        try {
            now = hashInput(f.role, f.path).hash;
        } catch (const InputError&) {
            changed.push_back(f.role + " " + f.path + " is gone (it hashed to " + hashHex(f.hash) + ")");
            continue;
        }
        if (now != f.hash)
            changed.push_back(f.role + " " + f.path + " changed (was " + hashHex(f.hash) + ", now " + hashHex(now) + ")");
    }
    return changed;
}

std::string formatInputs(const std::vector<InputFile>& inputs) {
    std::string out;
    for (const InputFile& f : inputs) out += f.role + " " + hashHex(f.hash) + " " + f.path + "\n";
    return out;
}

std::vector<InputFile> parseInputs(const std::string& text, const std::string& file) {
    std::vector<InputFile> inputs;
    std::istringstream lines(text);
    std::string line;
    for (int n = 1; std::getline(lines, line); ++n) {
        const auto a = line.find(' '), b = a == std::string::npos ? a : line.find(' ', a + 1);
        InputFile f;
        if (b == std::string::npos || b - a != 17 || b + 1 >= line.size())
            throw InputError(file, "/inputs/text line " + std::to_string(n), "expected \"<role> <16 hex digits> <path>\"");
        f.role = line.substr(0, a);
        for (char c : line.substr(a + 1, 16))
            if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f')))
                throw InputError(file, "/inputs/text line " + std::to_string(n), "the hash is not 16 lowercase hex digits");
        f.hash = std::stoull(line.substr(a + 1, 16), nullptr, 16);
        f.path = line.substr(b + 1);
        inputs.push_back(std::move(f));
    }
    return inputs;
}

}  // namespace shapevo
