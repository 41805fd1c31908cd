// The HDF5 layout is a public format: `h5ls -r` of a written island file and of run.h5 lists
// exactly the documented names (src/checkpoint/island_file.cpp and run_file.cpp).
#include <array>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "checkpoint_test_util.hpp"

namespace shapevo {
namespace {

/// The object names `h5ls -r` prints (first column), or nullopt if h5ls is not installed.
std::optional<std::set<std::string>> h5lsNames(const std::string& file) {
    if (std::system("command -v h5ls >/dev/null 2>&1") != 0) return std::nullopt;
    FILE* pipe = popen(("h5ls -r '" + file + "' 2>&1").c_str(), "r");
    if (!pipe) return std::nullopt;
    std::string out;
    std::array<char, 4096> buf;
    while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
    EXPECT_EQ(pclose(pipe), 0) << out;
    std::set<std::string> names;
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);) names.insert(line.substr(0, line.find(' ')));
    return names;
}

TEST(CheckpointLayout, IslandFileListsExactlyTheDocumentedNames) {
    test::TempDir dir;
    writeIslandFile(dir.file("island-0000.h5"), test::makeIsland(0));
    const auto names = h5lsNames(dir.file("island-0000.h5"));
    if (!names) GTEST_SKIP() << "h5ls (hdf5-tools) not installed";
    EXPECT_EQ(*names, (std::set<std::string>{"/", "/curve", "/migrants", "/migrants/fitness", "/migrants/gene_counts",
                                              "/migrants/genes", "/migrants/offsets", "/population", "/population/fitness",
                                              "/population/gene_counts", "/population/genes", "/population/offsets",
                                              "/rng", "/rng/state"}));
}

TEST(CheckpointLayout, RunFileListsExactlyTheDocumentedNames) {
    test::TempDir dir;
    writeRunMetadata(dir.file("run.h5"), test::makeRun(2));
    const auto names = h5lsNames(dir.file("run.h5"));
    if (!names) GTEST_SKIP() << "h5ls (hdf5-tools) not installed";
    EXPECT_EQ(*names, (std::set<std::string>{"/", "/config", "/config/text", "/curve", "/grammar", "/grammar/text", "/inputs",
                                              "/inputs/text"}));
}

}  // namespace
}  // namespace shapevo
