// Every relative link and picture in every markdown file of the repository resolves: walks each
// *.md outside build*/ folders, .git and runs/, and checks that the target of every inline link
// `[text](target)`, picture `![alt](target)` and HTML `<img src="target">` exists, relative to the
// file (anchors and queries are cut off and not checked; links with a scheme, such as https:, and
// links inside code spans or fenced code blocks are not checked).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "../test_support.hpp"

namespace shapevo {
namespace {

namespace fs = std::filesystem;

/// Every markdown file of the repository at `root`, skipping build folders, .git and runs/.
std::vector<fs::path> docsMarkdownFiles(const fs::path& root) {
    std::vector<fs::path> files;
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        const std::string name = it->path().filename().string();
        if (it->is_directory() && (name == ".git" || name == "runs" || (it.depth() == 0 && name.rfind("build", 0) == 0))) {
            it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file() && it->path().extension() == ".md") files.push_back(it->path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// `text` with fenced code blocks and inline code spans blanked (line breaks kept, so that
/// line numbers stay right).
std::string docsWithoutCode(const std::string& text) {
    std::string out;
    bool fenced = false;
    for (const std::string& line : test::splitLines(text)) {
        const auto first = line.find_first_not_of(' ');
        const bool fence = first != std::string::npos && (line.compare(first, 3, "```") == 0 || line.compare(first, 3, "~~~") == 0);
        if (fence) fenced = !fenced;
        if (fence || fenced || line.rfind("    ", 0) == 0) {
            out += '\n';
            continue;
        }
        std::string kept;
        bool inSpan = false;
        for (char c : line) {
            if (c == '`') inSpan = !inSpan;
            else if (!inSpan) kept += c;
        }
        out += kept + '\n';
    }
    return out;
}

struct DocsLink {
    int line = 0;
    std::string target;
};

/// The relative targets of the links and pictures of one markdown text.
std::vector<DocsLink> docsRelativeLinks(const std::string& markdown) {
    static const std::regex inlineLink(R"re(\]\(\s*<?([^)\s>]+)>?(\s+"[^"]*")?\s*\))re");
    static const std::regex htmlImage(R"re(<img[^>]*\ssrc\s*=\s*"([^"]+)")re", std::regex::icase);
    static const std::regex scheme(R"re(^[A-Za-z][A-Za-z0-9+.-]*:)re");
    std::vector<DocsLink> links;
    int lineNumber = 0;
    for (const std::string& line : test::splitLines(docsWithoutCode(markdown))) {
        ++lineNumber;
        for (const std::regex* pattern : {&inlineLink, &htmlImage})
            for (auto it = std::sregex_iterator(line.begin(), line.end(), *pattern); it != std::sregex_iterator(); ++it) {
                std::string target = (*it)[1].str();
                if (target.empty() || target[0] == '#' || std::regex_search(target, scheme)) continue;
                target = target.substr(0, target.find_first_of("#?"));
                for (std::size_t at = target.find("%20"); at != std::string::npos; at = target.find("%20")) target.replace(at, 3, " ");
                links.push_back({lineNumber, target});
            }
    }
    return links;
}

/// "file:line: target" for every link of `file` whose target does not exist.
std::vector<std::string> docsBrokenLinks(const fs::path& file, const fs::path& root) {
    std::vector<std::string> broken;
    for (const DocsLink& link : docsRelativeLinks(test::readFile(file.string()))) {
        const fs::path target = link.target[0] == '/' ? root / link.target.substr(1) : file.parent_path() / link.target;
        if (!fs::exists(target))
            broken.push_back(fs::relative(file, root).string() + ":" + std::to_string(link.line) + ": " + link.target);
    }
    return broken;
}

TEST(DocsLinks, EveryRelativeLinkAndPictureInEveryMarkdownFileResolves) {
    const fs::path root = SHAPEVO_SOURCE_DIR;
    const std::vector<fs::path> files = docsMarkdownFiles(root);
    ASSERT_GE(files.size(), 10u) << "the walk found too few markdown files under " << root;
    std::string report;
    std::size_t checked = 0;
    for (const fs::path& file : files) {
        checked += docsRelativeLinks(test::readFile(file.string())).size();
        for (const std::string& b : docsBrokenLinks(file, root)) report += "  " + b + "\n";
    }
    EXPECT_GE(checked, 50u) << "too few links found: is the link pattern right?";
    EXPECT_EQ(report, "") << "links and pictures whose target does not exist:\n" << report;
}

TEST(DocsLinks, ABrokenLinkOrPictureIsFoundAndCodeIsNot) {
    test::TempDir dir;
    fs::create_directories(dir.path() / "docs");
    { std::FILE* f = std::fopen(dir.file("docs/here.png").c_str(), "w"); std::fclose(f); }
    const std::string page =
        "# page\n"
        "[ok](here.png) ![ok](./here.png \"title\") [web](https://example.org/x) [anchor](#page) [ok](here.png#x)\n"
        "[missing](nowhere.md) and ![missing picture](figures/gone.png)\n"
        "`[code](not-checked.md)`\n"
        "```\n[fenced](not-checked.md)\n```\n"
        "<img src=\"gone-too.png\" width=\"40\">\n";
    { std::FILE* f = std::fopen(dir.file("docs/page.md").c_str(), "w"); std::fputs(page.c_str(), f); std::fclose(f); }
    const std::vector<std::string> broken = docsBrokenLinks(dir.path() / "docs/page.md", dir.path());
    EXPECT_EQ(broken, (std::vector<std::string>{"docs/page.md:3: nowhere.md", "docs/page.md:3: figures/gone.png",
                                                "docs/page.md:8: gone-too.png"}));
}

}  // namespace
}  // namespace shapevo
