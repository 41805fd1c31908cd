// loadGrammar reads a file and reports unreadable files as InputError naming the path.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "grammar/front_ends.hpp"
#include "base/input_error.hpp"

namespace shapevo {
namespace {

TEST(GrammarLoad, MissingFileThrowsInputErrorNamingThePath) {
    const std::string path = (std::filesystem::temp_directory_path() / "shapevo_no_such_dir/none.grammar").string();
    try {
        loadGrammar(path);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(std::string(e.what()), path + ": cannot open grammar file");
    }
}

TEST(GrammarLoad, DirectoryIsNotAGrammar) {
    const std::string dir = std::filesystem::temp_directory_path().string();
    EXPECT_THROW(loadGrammar(dir), InputError);
}

TEST(GrammarLoad, ParseErrorsNameTheFileThatWasRead) {
    const auto path = std::filesystem::temp_directory_path() / ("shapevo_load_test_" + std::to_string(::getpid()) + ".grammar");
    {
        std::ofstream out(path);
        out << "start A\nrule A {\n  rotate q 3\n}\n";
    }
    try {
        loadGrammar(path.string());
        std::filesystem::remove(path);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        std::filesystem::remove(path);
        EXPECT_EQ(std::string(e.what()).rfind(path.string() + ":3:10: ", 0), 0u) << e.what();
    }
}

TEST(GrammarLoad, ReadsTheWholeFileAndKeepsItsText) {
    const std::string path = std::string(SHAPEVO_SOURCE_DIR) + "/grammars/coral.grammar";
    const Grammar g = loadGrammar(path);
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(g.source, text);
    EXPECT_EQ(g.path, path);
}

}  // namespace
}  // namespace shapevo
