// Every shapevo command the documentation shows is one shapevo accepts: each `shapevo ...` line
// of a fenced code block (README.md, docs/ but its history/ and generated reference/, the
// cluster, grammar and graph-file READMEs) is parsed by the binary (SHAPEVO_CHECK_ARGUMENTS=1: command,
// options and option values checked, nothing run); the quick ones that need only shipped files
// (sample, translate, reference) are run to the end in a temporary folder. In a block whose
// commands carry a "$ " prompt, the other lines are output and are not commands.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../test_support.hpp"

namespace shapevo {
namespace {

namespace fs = std::filesystem;

struct DocsCommand {
    std::string place;  ///< "docs/own-grammar.md:12"
    std::vector<std::string> words;  ///< after the binary: {"sample", "grammars/castle.grammar", ...}
};

std::vector<std::string> docsCommandFiles() {
    std::vector<std::string> files{"README.md", "cluster/README.md", "grammars/README.md", "grammars/castlemaker/README.md",
                                   "grammars/pcg/README.md"};
    for (const auto& entry : fs::directory_iterator(test::sourcePath("docs")))
        if (entry.path().extension() == ".md") files.push_back("docs/" + entry.path().filename().string());
    return files;
}

/// The words of a shell line, quotes removed, cut at a comment.
std::vector<std::string> shellWords(const std::string& line) {
    std::vector<std::string> words;
    std::string word;
    bool inWord = false;
    char quote = 0;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quote) {
            if (c == quote) quote = 0;
            else word += c;
        } else if (c == '\'' || c == '"') {
            quote = c, inWord = true;
        } else if (c == '#' && !inWord) {
            break;
        } else if (c == ' ' || c == '\t') {
            if (inWord) words.push_back(word), word.clear(), inWord = false;
        } else {
            word += c, inWord = true;
        }
    }
    if (inWord) words.push_back(word);
    return words;
}

/// `line` without its indentation (a fenced block may sit in a list item).
std::string unindented(const std::string& line) {
    const auto start = line.find_first_not_of(" \t");
    return start == std::string::npos ? "" : line.substr(start);
}

/// The shapevo commands of the fenced blocks of `file` (relative to the source).
std::vector<DocsCommand> commandsOf(const std::string& file) {
    std::ifstream in(test::sourcePath(file));
    std::stringstream text;
    text << in.rdbuf();
    std::vector<std::string> lines = test::splitLines(text.str());
    for (std::string& line : lines) line = unindented(line);
    std::vector<DocsCommand> out;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].rfind("```", 0) != 0) continue;
        std::size_t end = i + 1;
        bool prompted = false;
        for (; end < lines.size() && lines[end].rfind("```", 0) != 0; ++end) prompted = prompted || lines[end].rfind("$ ", 0) == 0;
        for (std::size_t k = i + 1; k < end; ++k) {
            std::string line = lines[k];
            if (prompted && line.rfind("$ ", 0) != 0) continue;
            if (prompted) line = line.substr(2);
            std::vector<std::string> words = shellWords(line);
            std::size_t w = 0;
            while (w < words.size() && words[w].find('=') != std::string::npos && words[w][0] != '-') ++w;  // VAR=value
            if (w < words.size() && words[w] == "mpirun") {  // mpirun's own options, up to the binary
                while (w < words.size() && !(words[w] == "shapevo" || words[w].ends_with("/shapevo"))) ++w;
            }
            if (w >= words.size() || !(words[w] == "shapevo" || words[w].ends_with("/shapevo"))) continue;
            out.push_back({file + ":" + std::to_string(k + 1), std::vector<std::string>(words.begin() + long(w) + 1, words.end())});
        }
        i = end;
    }
    return out;
}

std::string quotedArguments(const std::vector<std::string>& words, const std::string& pwd) {
    std::string out;
    for (std::string w : words) {
        for (auto at = w.find("$PWD"); at != std::string::npos; at = w.find("$PWD")) w.replace(at, 4, pwd);
        out += " '" + w + "'";
    }
    return out;
}

TEST(DocsCommands, EveryShapevoCommandInTheDocsIsOneShapevoAccepts) {
    const test::TempDir dir;
    int checked = 0, ran = 0;
    for (const std::string& file : docsCommandFiles()) {
        for (const DocsCommand& c : commandsOf(file)) {
            ASSERT_FALSE(c.words.empty()) << c.place;
            const std::string args = quotedArguments(c.words, dir.path().string());
            const auto parsed = test::runCommand("SHAPEVO_CHECK_ARGUMENTS=1 " + std::string(SHAPEVO_BIN) + args);
            EXPECT_EQ(parsed.exitCode, 0) << c.place << ": shapevo" << args << "\n" << parsed.output;
            ++checked;
            const std::string& command = c.words.front();
            if (command != "sample" && command != "translate" && command != "reference") continue;
            // Quick and self-contained: run it where the shipped folders are, writing into a fresh folder.
            const fs::path work = dir.path() / ("ran-" + std::to_string(ran++));
            fs::create_directories(work);
            for (const char* shipped : {"configs", "grammars", "targets"})
                fs::create_directory_symlink(test::sourcePath(shipped), work / shipped);
            const auto result = test::runCommand("cd '" + work.string() + "' && " + std::string(SHAPEVO_BIN) + args + " >/dev/null");
            EXPECT_EQ(result.exitCode, 0) << c.place << ": shapevo" << args << "\n" << result.output;
        }
    }
    EXPECT_GT(checked, 20) << "the docs show fewer commands than they did";
    EXPECT_GT(ran, 2);
}

TEST(DocsCommands, AWrongOptionOrCommandIsCaught) {
    const auto wrongOption = test::runCommand("SHAPEVO_CHECK_ARGUMENTS=1 " + std::string(SHAPEVO_BIN) + " sample g.grammar --no-such-option -o x.obj");
    EXPECT_EQ(wrongOption.exitCode, 2) << wrongOption.output;
    const auto wrongCommand = test::runCommand("SHAPEVO_CHECK_ARGUMENTS=1 " + std::string(SHAPEVO_BIN) + " sprout g.grammar");
    EXPECT_EQ(wrongCommand.exitCode, 2) << wrongCommand.output;
    const auto words = shellWords("mpirun -np 2 build/shapevo run 'a b.toml' --set x=1   # two islands");
    EXPECT_EQ(words, (std::vector<std::string>{"mpirun", "-np", "2", "build/shapevo", "run", "a b.toml", "--set", "x=1"}));
}

}  // namespace
}  // namespace shapevo
