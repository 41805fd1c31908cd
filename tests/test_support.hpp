// Helpers shared by the tests: paths into the source tree, a temporary folder per test, running
// the binary, and small text and error checks (splitLines, rightNested, expectInputError).
#pragma once
#include <algorithm>
#include <filesystem>
#include <functional>
#include <sstream>
#include <vector>
#include <unistd.h>
#include <string>

#include <gtest/gtest.h>

#include "base/input_error.hpp"

namespace shapevo::test {

inline std::string sourcePath(const std::string& relative) { return std::string(SHAPEVO_SOURCE_DIR) + "/" + relative; }
/// The spaceship scene's config, the one most CLI tests run.
inline std::string spaceshipConfig() { return sourcePath("configs/spaceship.toml"); }
/// Every shipped grammar, CastleMaker rule file and procedural content graph (.grammar, .rule and
/// .pcg files in grammars/, grammars/castlemaker/ and grammars/pcg/), sorted.
inline std::vector<std::string> shippedGrammarFiles() {
    std::vector<std::string> paths;
    for (const char* folder : {"grammars", "grammars/castlemaker", "grammars/pcg"})
        for (const auto& entry : std::filesystem::directory_iterator(sourcePath(folder))) {
            const std::string ext = entry.path().extension().string();
            if (ext == ".grammar" || ext == ".rule" || ext == ".pcg") paths.push_back(entry.path().string());
        }
    std::sort(paths.begin(), paths.end());
    return paths;
}

/// A fresh empty directory under the system temp dir, removed when the object goes away.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        // The process id too: ctest -j runs test processes side by side, and a folder made
        // outside a test (a fixture's set-up) would otherwise have the same name in each.
        std::string name = std::string("shapevo-") + (info ? std::string(info->test_suite_name()) + "-" + info->name() : "t") + "-" +
                           std::to_string(::getpid());
        for (char& c : name)
            if (c == '/') c = '_';
        path_ = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() { std::filesystem::remove_all(path_); }
    const std::filesystem::path& path() const { return path_; }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

}  // namespace shapevo::test

#include <array>
#include <cstdio>
#include <sys/wait.h>

namespace shapevo::test {

struct CommandResult {
    int exitCode = -1;
    std::string output;  ///< stdout and stderr together
};

/// Run a shell command, capturing stdout and stderr together.
inline CommandResult runCommand(const std::string& command) {
    CommandResult r;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf;
    while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe)) r.output.append(buf.data(), n);
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

/// Run the shapevo binary with `args` (a shell-quoted string).
inline CommandResult runShapevo(const std::string& args) { return runCommand(std::string(SHAPEVO_BIN) + " " + args); }

/// Whether the ranks that mpirunWords() starts check for leaks (see LeakCheckedRanks).
inline bool& mpiRanksCheckLeaks() {
    static bool on = false;
    return on;
}

/// While one is alive, ranks started by mpirunWords() run LeakSanitizer (under AddressSanitizer).
/// By default they do not: OpenMPI keeps allocations until exit, and telling those from ours
/// means unwinding every allocation fully and symbolizing at exit, 1.7 s more for every 2-rank
/// launch (2.4 s against 0.7 s), most of the sanitizer pass's MPI time. The tests that take each
/// MPI path hold one — sync islands with a checkpoint and resume, async islands, a damaged
/// checkpoint, a forged island (and the mpi.* scripts, whose ranks always check) — so the island
/// code still runs under LeakSanitizer; the other MPI tests keep AddressSanitizer and UBSan.
class LeakCheckedRanks {
public:
    LeakCheckedRanks() { mpiRanksCheckLeaks() = true; }
    ~LeakCheckedRanks() { mpiRanksCheckLeaks() = false; }
    LeakCheckedRanks(const LeakCheckedRanks&) = delete;
    LeakCheckedRanks& operator=(const LeakCheckedRanks&) = delete;
};

/// The shell words that start `ranks` MPI ranks (oversubscribed, root allowed, as CI needs).
/// Under AddressSanitizer (ASAN_OPTIONS set) leak-checked ranks (LeakCheckedRanks) unwind every
/// allocation fully: OpenMPI's plug-ins keep allocations until exit, and only a full stack
/// reaches the MPI library that tests/lsan.supp names; the others skip LeakSanitizer.
/// OpenMPI's session folder of this test process, apart from every other one: mpiruns of tests
/// running side by side (ctest -j) share /tmp/ompi.<host>.<uid> otherwise, and one that ends may
/// remove it while another creates its own folder in it ("orte_session_dir failed").
inline std::string mpiSessionBase() {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("shapevo-ompi-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir.string();
}

inline std::string mpirunWords(int ranks) {
    const char* asan = mpiRanksCheckLeaks() ? "${ASAN_OPTIONS:+ASAN_OPTIONS=$ASAN_OPTIONS:fast_unwind_on_malloc=0} "
                                            : "${ASAN_OPTIONS:+ASAN_OPTIONS=$ASAN_OPTIONS:detect_leaks=0} ";
    return std::string("env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ") + asan +
           std::string(SHAPEVO_MPIRUN) + " --mca orte_tmpdir_base " + mpiSessionBase() + " --oversubscribe -np " +
           std::to_string(ranks);
}

/// Run shapevo on `ranks` MPI ranks.
inline CommandResult runShapevoMpi(int ranks, const std::string& args) {
    return runCommand(mpirunWords(ranks) + " " + std::string(SHAPEVO_BIN) + " " + args);
}

/// curve.csv without its seconds column (the only column that differs between repeated runs).
inline std::string curveWithoutTime(const std::string& csv) {
    std::string out;
    std::size_t start = 0;
    while (start < csv.size()) {
        std::size_t end = csv.find('\n', start);
        if (end == std::string::npos) end = csv.size();
        const std::string line = csv.substr(start, end - start);
        const auto a = line.find(','), b = line.find(',', a + 1);
        out += line.substr(0, a) + line.substr(b) + "\n";
        start = end + 1;
    }
    return out;
}

/// The text of `key`'s value in summary.json (a number, as written).
inline std::string summaryValue(const std::string& summary, const std::string& key) {
    const std::string quoted = "\"" + key + "\": ";
    const auto at = summary.find(quoted);
    if (at == std::string::npos) return "(no " + key + ")";
    const auto from = at + quoted.size();
    return summary.substr(from, summary.find_first_of(",\n}", from) - from);
}

/// The word after `key ` in `shapevo evaluate`'s line ("fitness 0.5  silhouette_iou 0.2 ...").
inline std::string evaluatedValue(const std::string& output, const std::string& key) {
    const auto at = output.find(key + " ");
    if (at == std::string::npos) return "(no " + key + ")";
    const auto from = at + key.size() + 1;
    return output.substr(from, output.find_first_of(" \n", from) - from);
}

inline std::string readFile(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return {};
    std::string s;
    std::array<char, 4096> buf;
    while (std::size_t n = std::fread(buf.data(), 1, buf.size(), f)) s.append(buf.data(), n);
    std::fclose(f);
    return s;
}

inline void writeFile(const std::string& path, const std::string& text) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
}

/// Writes `grammarText` to `dir`/NAME.grammar (NAME`extension`: ".rule" for a CastleMaker rule file)
/// and a copy of configs/spaceship.toml that uses it (with the spaceship's target, by absolute
/// path) to `dir`/NAME.toml; returns the config's path.
inline std::string configWithGrammar(const TempDir& dir, const std::string& grammarText, const std::string& name = "g",
                                     const std::string& extension = ".grammar") {
    writeFile(dir.file(name + extension), grammarText);
    std::string cfg = readFile(sourcePath("configs/spaceship.toml"));
    auto replaceAll = [&cfg](const std::string& from, const std::string& to) {
        for (std::size_t at = cfg.find(from); at != std::string::npos; at = cfg.find(from, at + to.size()))
            cfg.replace(at, from.size(), to);
    };
    replaceAll("\"../grammars/spaceship.grammar\"", "\"" + name + extension + "\"");
    replaceAll("\"../targets/", "\"" + sourcePath("targets/"));
    writeFile(dir.file(name + ".toml"), cfg);
    return dir.file(name + ".toml");
}

/// The lines of `text`, without their line ends.
inline std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

/// n right-leaning additions "1 + (1 + (...))": an expression that needs an evaluation stack of n + 1.
inline std::string rightNested(int n) {
    std::string s = "1";
    for (int i = 0; i < n; ++i) s = "1 + (" + s + ")";
    return s;
}

/// Runs `f`, expects an InputError, checks that its message contains every fragment, returns it.
inline std::string expectInputError(const std::function<void()>& f, const std::vector<std::string>& fragments) {
    try {
        f();
        ADD_FAILURE() << "no InputError thrown";
    } catch (const InputError& e) {
        for (const auto& fragment : fragments)
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
                << "message '" << e.what() << "' lacks '" << fragment << "'";
        return e.what();
    }
    return "";
}

}  // namespace shapevo::test
