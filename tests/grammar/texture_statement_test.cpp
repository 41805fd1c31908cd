// The `texture NAME "FILE.png" (SX, SY)` statement: the image is read once when the grammar is
// loaded, relative to the grammar's folder, and kept in Grammar::textures with its material name;
// a missing, unreadable or non-PNG file and malformed arguments are each one InputError at the
// exact file:line:column with a message naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "../test_support.hpp"
#include "base/input_error.hpp"
#include "grammar/parser.hpp"

namespace shapevo {
namespace {

namespace fs = std::filesystem;

/// A grammar "in" tests/data, so that "bricks.png" names tests/data/bricks.png.
const std::string kDataGrammar = test::sourcePath("tests/data/texture.grammar");

std::string textureRuleBody(const std::string& lines) { return "start A\nrule A {\n" + lines + "\n  box\n}\n"; }

std::vector<std::uint8_t> bytesOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The message of the InputError that parsing `text` as `path` throws ("" if none).
std::string errorOf(const std::string& text, const std::string& path = kDataGrammar) {
    try {
        parseGrammar(text, path);
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path);
        return e.what();
    }
    return "";
}

TEST(TextureStatement, ReadsThePngRelativeToTheGrammarAndNamesItsMaterial) {
    const Grammar g = parseGrammar(textureRuleBody("  texture bricks \"bricks.png\" (2, scope.size.y * 3)"), kDataGrammar);
    ASSERT_EQ(g.textures.size(), 1u);
    const Texture& t = g.textures[0];
    EXPECT_EQ(t.name, "bricks");
    EXPECT_EQ(t.path, "bricks.png");
    EXPECT_EQ(t.file, fs::absolute(test::sourcePath("tests/data/bricks.png")).lexically_normal().string());
    EXPECT_EQ(t.png, bytesOf(test::sourcePath("tests/data/bricks.png")));
    ASSERT_LT(t.material, g.materialNames.size());
    EXPECT_EQ(g.materialNames[t.material], "bricks");
    EXPECT_TRUE(g.hasAppearance);
    const Statement& s = g.rules[0].statements[0];
    EXPECT_EQ(s.kind, StatementKind::Texture);
    EXPECT_EQ(s.slot, 0);
}

TEST(TextureStatement, AQuotedNameAndOneFileUnderTwoNamesReadOnce) {
    const Grammar g = parseGrammar(textureRuleBody("  texture \"old bricks\" \"bricks.png\" (1, 1)\n  texture bricks \"./bricks.png\" (1, 1)\n"
                                        "  texture \"old bricks\" \"bricks.png\" (3, 3)\n  material bricks"),
                                   kDataGrammar);
    ASSERT_EQ(g.textures.size(), 2u) << "the third statement reuses the first texture";
    EXPECT_EQ(g.textures[0].name, "old bricks");
    EXPECT_EQ(g.textures[1].file, g.textures[0].file) << "./bricks.png is the same file";
    EXPECT_EQ(g.textures[1].png, g.textures[0].png);
    EXPECT_EQ(g.rules[0].statements[2].slot, 0);
    EXPECT_EQ(g.materialNames, (std::vector<std::string>{"", "old bricks", "bricks"})) << "`material bricks` shares the name";
}

TEST(TextureStatement, AGrammarWithoutTexturesHasNone) {
    const Grammar g = parseGrammar(textureRuleBody("  color (1, 0, 0)"), kDataGrammar);
    EXPECT_TRUE(g.textures.empty());
}

TEST(TextureStatement, AMissingFileIsLocatedAtItsName) {
    EXPECT_EQ(errorOf(textureRuleBody("  texture bricks \"nope.png\" (1, 1)")),
              kDataGrammar + ":3:18: cannot open texture 'nope.png': no such file (" +
                  fs::absolute(test::sourcePath("tests/data/nope.png")).lexically_normal().string() + ")");
}

// Regression (fuzz_grammar_parser): an empty file name made an empty path, and
// std::filesystem::absolute threw a filesystem_error that ended the program.
TEST(TextureStatement, AnEmptyFileNameIsLocatedAtItsName) {
    EXPECT_EQ(errorOf(textureRuleBody("  texture t \"\" (1, 1)"), "g.grammar"),
              "g.grammar:3:13: the texture's file name is empty (expected a PNG image, relative to the grammar's folder)");
}

TEST(TextureStatement, AFileThatIsNotAPngIsLocatedAtItsName) {
    const test::TempDir dir;
    const std::string grammar = dir.file("g.grammar");
    std::ofstream(dir.file("text.png")) << "hello, not an image\n";
    std::ofstream(dir.file("empty.png")).flush();
    fs::create_directory(dir.path() / "folder.png");
    const auto png = bytesOf(test::sourcePath("tests/data/bricks.png"));
    std::ofstream(dir.file("cut.png"), std::ios::binary).write(reinterpret_cast<const char*>(png.data()), 40);
    EXPECT_EQ(errorOf(textureRuleBody("  texture t \"text.png\" (1, 1)"), grammar),
              grammar + ":3:13: texture 'text.png' is not a PNG (it does not start with the PNG signature)");
    EXPECT_EQ(errorOf(textureRuleBody("  texture t \"empty.png\" (1, 1)"), grammar),
              grammar + ":3:13: texture 'empty.png' is not a PNG (the file is empty)");
    EXPECT_EQ(errorOf(textureRuleBody("  texture t \"folder.png\" (1, 1)"), grammar),
              grammar + ":3:13: cannot open texture 'folder.png': not a regular file");
    EXPECT_EQ(errorOf(textureRuleBody("  texture t \"cut.png\" (1, 1)"), grammar),
              grammar + ":3:13: texture 'cut.png' is not a readable PNG: truncated PNG: the file ends before the image does");
}

TEST(TextureStatement, MalformedArgumentsAreLocated) {
    const std::string at = kDataGrammar + ":3:";
    EXPECT_EQ(errorOf(textureRuleBody("  texture 5 \"bricks.png\" (1, 1)")),
              at + "11: expected a material name after 'texture' (a word or \"text\"), found number 5");
    EXPECT_EQ(errorOf(textureRuleBody("  texture \"bricks.png\" (1, 1)")),
              at + "24: expected the texture's file name in quotes after 'texture bricks.png' (a PNG image, relative to the "
                   "grammar's folder), found '('");
    EXPECT_EQ(errorOf(textureRuleBody("  texture bricks bricks (1, 1)")),
              at + "18: expected the texture's file name in quotes after 'texture bricks' (a PNG image, relative to the "
                   "grammar's folder), found 'bricks'");
    EXPECT_EQ(errorOf(textureRuleBody("  texture bricks \"bricks.png\" 2")),
              at + "31: expected '(' after the texture's file name (its stretch factors (SX, SY) follow), found number 2");
    EXPECT_EQ(errorOf(textureRuleBody("  texture bricks \"bricks.png\" (2)")),
              at + "33: expected ',' between the texture's stretch factors (SX, SY), found ')'");
    EXPECT_EQ(errorOf(textureRuleBody("  texture bricks \"bricks.png\" (2, 1 box")),
              at + "37: expected ')' to close the texture's stretch factors (SX, SY), found 'box'");
    EXPECT_EQ(errorOf(textureRuleBody("  texture bricks \"bricks.png\" (scope.size, 1)")),
              at + "32: expected a scalar expression here, but this expression is a 3-vector (use .x, .y or .z)");
    EXPECT_EQ(errorOf(textureRuleBody("  texture bricks \"bricks.png\" (1, nope)")).rfind(at + "35: unknown name 'nope': expected a parameter", 0), 0u);
}

}  // namespace
}  // namespace shapevo
