// Every malformed grammar is rejected with an InputError that names file:line:column of the
// offending token and says specifically what is wrong (and, where it helps, what was expected).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../test_support.hpp"
#include "grammar/expression.hpp"
#include "grammar/front_ends.hpp"
#include "base/input_error.hpp"
#include "malformed_grammar_cases.hpp"

namespace shapevo {
namespace {

using malformed_grammar::Malformed;
using malformed_grammar::body;


const std::vector<Malformed>& cases() {
    static const std::vector<Malformed> all = {
        // --- lexical ---------------------------------------------------------------------
        {"StatementsNestedTooDeep", body("  " + std::string(300, '[') + " box " + std::string(300, ']')), "bad.grammar:3:259",
         "statements are nested more than 256 deep"},
        {"IfBlocksNestedTooDeep", [] {
             std::string s = "  ";
             for (int k = 0; k < 300; ++k) s += "if (1) { ";
             return body(s + "box" + std::string(300, '}'));
         }(), "bad.grammar:3:2307", "statements are nested more than 256 deep"},
        {"UnexpectedCharacter", "start A\nrule A { box @ }\n", "bad.grammar:2:14", "unexpected character '@'"},
        {"UnexpectedControlByte", "start A\nrule A {\x01}\n", "bad.grammar:2:9", "unexpected character 'byte 1'"},
        {"UnclosedString", body("  child \"oops"), "bad.grammar:3:9", "string is not closed before the end of the line"},
        {"MalformedNumber", body("  size 1.2.3"), "bad.grammar:3:8", "malformed number '1.2.3'"},
        {"NumberOutOfFloatRange", body("  size 1e39"), "bad.grammar:3:8", "number '1e39' is out of range"},
        {"NumberOutOfDoubleRange", body("  param p = uniform(0, 1e999)"), "bad.grammar:3:24", "number '1e999' is out of range"},
        // --- top level -------------------------------------------------------------------
        {"EmptyGrammar", "", "bad.grammar:1:1", "the grammar has no rules"},
        {"OnlyComments", "# nothing here\n", "bad.grammar:2:1", "the grammar has no rules"},
        {"MissingStart", "rule A { box }\n", "bad.grammar:1:1", "the grammar has no 'start NAME' line"},
        {"StartRuleUndefined", "start Main\nrule A { box }\n", "bad.grammar:1:7", "start rule 'Main' is not defined"},
        {"StartGivenTwice", "start A\nstart A\nrule A { }\n", "bad.grammar:2:1", "'start' is given twice"},
        {"StartWithoutName", "start 5\n", "bad.grammar:1:7", "expected the name of the start rule after 'start', found number 5"},
        {"SetOfAnUndeclaredAttribute", body("  set tone = 1"), "bad.grammar:3:7",
         "'tone' is not a carried attribute: declare it at the top level first (carry tone = VALUE)"},
        {"CarriedAttributeDeclaredTwice", "carry a = 1\ncarry a = 2\nstart A\nrule A { box }\n", "bad.grammar:2:7",
         "carried attribute 'a' is declared twice"},
        {"CarriedAttributeNamedLikeAnAttr", "attr a = 1\ncarry a = 2\nstart A\nrule A { box }\n", "bad.grammar:2:7",
         "'a' is already an attr"},
        {"AttrNamedLikeACarriedAttribute", "carry a = 1\nattr a = 2\nstart A\nrule A { box }\n", "bad.grammar:2:6",
         "'a' is already a carried attribute"},
        {"CarriedDefaultIsNotConstant", "carry a = scope.size.x\nstart A\nrule A { box }\n", "bad.grammar:1:11",
         "must be known when the grammar is read"},
        {"SetInsideTerminal", "carry a = 1\nstart A\nrule A {\n  terminal { set a = 2 }\n}\n", "bad.grammar:4:14",
         "'set' cannot be used inside 'terminal { }'"},
        {"UnknownTopLevelItem", "start A\nbox\n", "bad.grammar:2:1", "expected 'start', 'attr', 'carry' or 'rule' at the top level, found 'box'"},
        {"DuplicateRule", "start A\nrule A { box }\nrule A { box }\n", "bad.grammar:3:6", "rule 'A' is defined twice (first at line 2)"},
        {"RuleWithoutBrace", "start A\nrule A box\n", "bad.grammar:2:8", "expected '{' to open the body of rule A, found 'box'"},
        {"MissingCloseBraceAtEof", "start A\nrule A {\n  box\n", "bad.grammar:4:1",
         "expected '}' to close rule A (opened at line 2), found end of file"},
        {"DuplicateAttr", "attr h = 1\nattr h = 2\nstart A\nrule A { }\n", "bad.grammar:2:6", "attr 'h' is defined twice"},
        {"AttrWithoutNumber", "attr h = wide\nstart A\nrule A { }\n", "bad.grammar:1:10", "unknown name 'wide'"},
        {"AttrWithReservedName", "attr scope = 1\nstart A\nrule A { }\n", "bad.grammar:1:6", "'scope' is a reserved name"},
        // --- statements ------------------------------------------------------------------
        {"UnknownStatement", body("  extrusion 2"), "bad.grammar:3:3", "unknown statement 'extrusion'"},
        {"StatementIsANumber", body("  5"), "bad.grammar:3:3", "expected a statement (param, let, set, scale, size, translate, rotate, mirror, box, cylinder, cone, sphere, mesh, roof, paraboloid, color, material, texture, extrude, split, repeat, comp, lot, center, corners, edges, copy, if, case, terminal, child, send, gather or the name of a rule to run inline), found number 5"},
        {"MeshWithoutFileName", body("  mesh leaf"), "bad.grammar:3:8", "expected a file name in quotes after 'mesh', found 'leaf'"},
        {"MeshFileMissing", body("  mesh \"no-such-leaf.obj\""), "bad.grammar:3:8", "mesh \"no-such-leaf.obj\": "},
        {"TextureFileMissing", body("  texture bricks \"no-such-bricks.png\" (1, 1)"), "bad.grammar:3:18",
         "cannot open texture 'no-such-bricks.png': no such file"},
        {"TerminalWithChild", body("  terminal { child A prob 0.5 }"), "bad.grammar:3:14", "'child' cannot be used inside 'terminal { }'"},
        {"TerminalWithMirror", body("  terminal { mirror x }"), "bad.grammar:3:14", "'mirror' cannot be used inside 'terminal { }'"},
        {"TerminalNested", body("  terminal { terminal { box } }"), "bad.grammar:3:14", "'terminal' blocks cannot be nested"},
        {"TerminalUnclosed", "start A\nrule A {\n  terminal { box\n", "bad.grammar:4:1", "'}' to close rule A (opened at line 2)"},
        {"ConeTopWithoutExpression", body("  cone top"), "bad.grammar:4:1", "expected"},
        {"RoofTopMissingSecondFraction", body("  roof top (1)"), "bad.grammar:3:14",
         "expected ',' between the two fractions of 'roof top (X, Z)', found ')'"},
        {"RoofTopWithoutParenthesis", body("  roof top 0.5"), "bad.grammar:3:12",
         "expected '(' after 'roof top' (the form is roof top (X, Z)), found number 0.5"},
        {"RoofTopWithoutFractions", body("  roof top"), "bad.grammar:4:1",
         "expected '(' after 'roof top' (the form is roof top (X, Z)), found '}'"},
        {"RoofTopUnclosed", body("  roof top (1, 0.5 box"), "bad.grammar:3:20",
         "expected ')' after the two fractions of 'roof top (X, Z)', found 'box'"},
        {"RoofTopThreeFractions", body("  roof top (1, 0.5, 0)"), "bad.grammar:3:19",
         "expected ')' after the two fractions of 'roof top (X, Z)', found ','"},
        {"RoofTopVectorFraction", body("  roof top (scope.size, 1)"), "bad.grammar:3:13",
         "expected a scalar expression here, but this expression is a 3-vector"},
        {"RoofUnknownForm", body("  roof flat"), "bad.grammar:3:8",
         "expected a roof form after 'roof' (top (X, Z), gable, hip or pyramid) or the next statement, found 'flat'"},
        {"RoofFormIsANumber", body("  roof 0.5"), "bad.grammar:3:8",
         "expected a roof form after 'roof' (top (X, Z), gable, hip or pyramid) or the next statement, found number 0.5"},
        {"ParaboloidWithArguments", body("  paraboloid top 1"), "bad.grammar:3:14",
         "expected the next statement after 'paraboloid' (it takes no arguments), found 'top'"},
        {"RotateBadAxis", body("  rotate w 30"), "bad.grammar:3:10", "expected an axis x, y or z after 'rotate', found 'w'"},
        {"MirrorBadAxis", body("  mirror xy"), "bad.grammar:3:10", "expected an axis x, y or z after 'mirror', found 'xy'"},
        {"MirrorWithoutAxis", body("  mirror"), "bad.grammar:4:1", "expected an axis x, y or z after 'mirror', found '}'"},
        // --- params and priors -----------------------------------------------------------
        {"DuplicateParam", body("  param s = uniform(0, 1)\n  param s = uniform(0, 2)"), "bad.grammar:4:9",
         "parameter 's' is declared twice in rule A"},
        {"ReservedParamNamePi", body("  param pi = uniform(0, 1)"), "bad.grammar:3:9", "parameter name 'pi' is reserved"},
        {"ReservedParamNameFunction", body("  param sin = uniform(0, 1)"), "bad.grammar:3:9", "parameter name 'sin' is reserved"},
        {"ParamNameIsAnAttr", "attr h = 1\n" + body("  param h = uniform(0, 1)"), "bad.grammar:4:9", "parameter name 'h' is already an attr"},
        {"UnknownPrior", body("  param s = gauss(0, 1)"), "bad.grammar:3:13", "unknown prior 'gauss': expected uniform, normal, int or choice"},
        {"UniformLowAboveHigh", body("  param s = uniform(2, 1)"), "bad.grammar:3:13", "uniform(a, b) needs a <= b, got 2 > 1"},
        {"UniformVectorComponentLowAboveHigh", body("  param s = uniform((0, 5, 0), (1, 1, 1))"), "bad.grammar:3:13",
         "uniform(a, b) needs a <= b, got 5 > 1"},
        {"UniformMissingSecondArgument", body("  param s = uniform(1)"), "bad.grammar:3:22",
         "expected ',' between the two arguments of uniform, found ')'"},
        {"NormalWithoutBounds", body("  param s = normal(0, 1)\n  box"), "bad.grammar:4:3",
         "expected 'in [lo, hi]' after normal(mu, sigma): its support must be bounded, found 'box'"},
        {"NormalSigmaZero", body("  param s = normal(0, 0) in [0, 1]"), "bad.grammar:3:13", "normal(mu, sigma) needs sigma > 0, got 0"},
        {"NormalSigmaNegative", body("  param s = normal(0, -1) in [0, 1]"), "bad.grammar:3:13", "needs sigma > 0, got -1"},
        {"NormalBoundsReversed", body("  param s = normal(0, 1) in [1, -1]"), "bad.grammar:3:13", "needs lo <= hi, got 1 > -1"},
        {"IntWithVectors", body("  param n = int((1, 1, 1), (2, 2, 2))"), "bad.grammar:3:13", "int(a, b) takes two numbers, not vectors"},
        {"IntWithoutWholeNumber", body("  param n = int(0.2, 0.8)"), "bad.grammar:3:13", "int(0.2, 0.8) contains no whole number"},
        {"IntBoundTooLarge", body("  param n = int(0, 1e9)"), "bad.grammar:3:13", "int(a, b) bounds must lie within"},
        {"ChoiceOfAName", body("  param c = choice(1, big)"), "bad.grammar:3:23", "unknown name 'big'"},
        {"ChoiceEmpty", body("  param c = choice()"), "bad.grammar:3:20", "expected a number in choice(...), found ')'"},
        {"VectorConstantMissingComma", body("  param s = uniform((1, 2 3), 4)"), "bad.grammar:3:27",
         "expected ',' between the components of a vector (x, y, z), found number 3"},
        // --- child slots -----------------------------------------------------------------
        {"ProbAboveOne", body("  child B prob 1.5") + "rule B { }\n", "bad.grammar:3:16", "prob must be in [0, 1], got 1.5"},
        {"ProbNegative", body("  child B prob -0.5") + "rule B { }\n", "bad.grammar:3:16", "prob must be in [0, 1], got -0.5"},
        {"ProbGivenTwice", body("  child B prob 0.5 prob 0.3") + "rule B { }\n", "bad.grammar:3:20", "'prob' is given twice for this child slot"},
        {"MaxZero", body("  child B max 0") + "rule B { }\n", "bad.grammar:3:15", "max must be a whole number from 1 to 64, got 0"},
        {"MaxNotWhole", body("  child B max 2.5") + "rule B { }\n", "bad.grammar:3:15", "max must be a whole number from 1 to 64, got 2.5"},
        {"MaxTooLarge", body("  child B max 65") + "rule B { }\n", "bad.grammar:3:15", "max must be a whole number from 1 to 64, got 65"},
        {"TooManyChildPositions", body("  child B max 64 prob 0.5\n  child B prob 0.5") + "rule B { }\n", "bad.grammar:4:3",
         "rule A has more than 64 child positions"},
        {"UndefinedChildRule", body("  child Wing prob 0.5"), "bad.grammar:3:9", "rule 'Wing' is not defined"},
        {"UndefinedAlternative", body("  child [1] A | [2] Wing prob 0.5"), "bad.grammar:3:21", "rule 'Wing' is not defined"},
        {"WeightZero", body("  child [0] B | [1] C prob 0.5") + "rule B { }\nrule C { }\n", "bad.grammar:3:10",
         "an alternative's weight must be > 0, got 0"},
        {"WeightNegative", body("  child [-2] B prob 0.5") + "rule B { }\n", "bad.grammar:3:10", "an alternative's weight must be > 0, got -2"},
        {"WeightsSumOverflows", body("  child [3e38] B | [3e38] B prob 0.5") + "rule B { }\n", "bad.grammar:3:3",
         "the weights of this child slot add up to more than"},
        {"WeightNotClosed", body("  child [2 B") + "rule B { }\n", "bad.grammar:3:12", "expected ']' after the weight, found 'B'"},
        {"ChildWithoutRule", body("  child prob 0.5"), "bad.grammar:3:9", "expected a rule name after 'child', found 'prob'"},
        {"RecursionNeverEnds", "start A\nrule A { child B }\nrule B { child A }\n", "bad.grammar:2:6",
         "recursion never ends: A -> B -> A are all probability-1 children"},
        {"SelfRecursionNeverEnds", "start A\nrule A { box child A }\n", "bad.grammar:2:6", "recursion never ends: A -> A"},
        {"RecursionThroughAnAlternative", "start A\nrule A { child [1] B | [1] A }\nrule B { }\n", "bad.grammar:2:6",
         "recursion never ends: A -> A"},
        {"RecursionInAnUnreachableRule", "start A\nrule A { }\nrule X { child Y }\nrule Y { child Y max 2 }\n",
         "bad.grammar:4:6", "recursion never ends: Y -> Y"},
        {"MandatorySubtreeTooLarge",
         "start A\nrule A { child B max 64 }\nrule B { child C max 64 }\nrule C { child D max 64 }\nrule D { child E max 64 }\nrule E { }\n",
         "bad.grammar:2:6", "rule A always derives more than 1,000,000 genes"},
        // --- the building language: arguments, conditions, splits, comp, lots, colours ---
        {"ArgumentsForARuleWithout", body("  child B(2) prob 0.5") + "rule B { }\n", "bad.grammar:3:10", "rule B takes no arguments"},
        {"ArgumentsMissing", body("  child B prob 0.5") + "rule B(lo, hi) { }\n", "bad.grammar:3:9", "rule B takes 2 argument(s) (lo, hi): write B(...)"},
        {"TooFewArguments", body("  child B(1) prob 0.5") + "rule B(lo, hi) { }\n", "bad.grammar:3:12", "rule B takes 2 arguments, this call gives 1"},
        {"TooManyArguments", body("  child B(1, 2, 3) prob 0.5") + "rule B(lo, hi) { }\n", "bad.grammar:3:15", "rule B takes 2 argument(s), this call gives more"},
        {"ArgumentNamedTwice", "start A\nrule A { }\nrule B(x, x) { }\n", "bad.grammar:3:11", "argument 'x' is named twice in rule B"},
        {"ArgumentReservedName", "start A\nrule A { }\nrule B(pi) { }\n", "bad.grammar:3:8", "'pi' is a reserved name and cannot name an argument"},
        {"ChildArgumentNotConstant", body("  param p = uniform(0, 1)\n  child B(p) prob 0.5") + "rule B(x) { }\n", "bad.grammar:4:11",
         "the arguments of a child must be known when the grammar is read"},
        {"StartRuleWithArguments", "start A\nrule A(x) { }\n", "bad.grammar:1:7", "start rule 'A' takes arguments"},
        {"ChoiceFromTheScope", body("  param w = choice(1, scope.size.x)"), "bad.grammar:3:23", "a constant here must be known when the grammar is read, so it cannot use scope.size"},
        {"ChoiceFromTheScopeOrigin", body("  param w = choice(1, scope.origin.x)"), "bad.grammar:3:23", "a constant here must be known when the grammar is read, so it cannot use scope.origin"},
        {"ChoiceFromTheScopeAxis", body("  param w = choice(scope.axis.z.y, 2)"), "bad.grammar:3:20", "a constant here must be known when the grammar is read, so it cannot use scope.axis"},
        {"ProbFromThePieceIndex", body("  child B prob piece.index") + "rule B { }\n", "bad.grammar:3:16", "a constant here must be known when the grammar is read, so it cannot use piece.index"},
        {"MaxFromThePieceCount", body("  child B max piece.count") + "rule B { }\n", "bad.grammar:3:15", "cannot use piece.count"},
        {"AttrFromThePieceIndex", "attr a = piece.index\nstart A\nrule A { }\n", "bad.grammar:1:10", "cannot use piece.index"},
        {"ChildArgumentFromTheScopeOrigin", body("  child B(scope.origin.x)") + "rule B(x) { }\n", "bad.grammar:3:11",
         "the arguments of a child must be known when the grammar is read"},
        {"ScopeUnknownField", body("  size scope.orign"), "bad.grammar:3:14", "expected 'size', 'origin' or 'axis' after 'scope.', found 'orign'"},
        {"ScopeAxisBadName", body("  size scope.axis.w"), "bad.grammar:3:19", "expected an axis x, y or z after 'scope.axis.', found 'w'"},
        {"ScopeAxisWithoutName", body("  size scope.axis"), "bad.grammar:4:1", "expected '.' after 'scope.axis'"},
        {"PieceUnknownField", body("  rotate x piece.size"), "bad.grammar:3:18", "expected 'index' or 'count' after 'piece.', found 'size'"},
        {"PieceIsAVector", body("  rotate x piece.index.x"), "bad.grammar:3:24", "'.x' applies to a 3-vector, but this is a scalar"},
        {"LengthOfAScalar", body("  rotate x length(2)"), "bad.grammar:3:19", "length takes 3-vectors (such as scope.origin or (x, y, z)), but this argument is a scalar"},
        {"DotOfAScalar", body("  rotate x dot(scope.origin, 1)"), "bad.grammar:3:30", "dot takes 3-vectors"},
        {"DistanceWithOneArgument", body("  rotate x distance(scope.origin)"), "bad.grammar:3:33", "expected ',' between the arguments of distance"},
        {"LengthIsAScalar", body("  translate length(scope.origin).x"), "bad.grammar:3:34", "'.x' applies to a 3-vector, but this is a scalar"},
        {"CopyWithoutCount", body("  copy B") + "rule B { }\n", "bad.grammar:3:8", "expected the number of copies before the successor (copy N SUCCESSOR)"},
        {"CopyWithoutSuccessor", body("  copy 3"), "bad.grammar:4:1", "expected a successor"},
        {"ChoiceFromAParameter", body("  param a = uniform(0, 1)\n  param b = choice(a, 2)"), "bad.grammar:4:20", "cannot use parameter 'a'"},
        {"RunTimePriorIsAVector", body("  param v = uniform(0, scope.size)"), "bad.grammar:3:24", "expected a scalar expression here"},
        {"WeightsSeparatedByComma", body("  child [0.25] B, [0.75] C") + "rule B { }\nrule C { }\n", "bad.grammar:3:17", "alternatives of a child slot are separated by '|', not ','"},
        {"ConditionIsAVector", body("  if (scope.size) { box }"), "bad.grammar:3:7", "a condition must be a scalar"},
        {"IfWithoutParentheses", body("  if scope.size.x > 1 { box }"), "bad.grammar:3:6", "expected '(' after 'if' (the condition goes in parentheses)"},
        {"ElseWithoutIf", body("  box\n  else { box }"), "bad.grammar:4:3", "'else' without an 'if' or 'case' block just before it"},
        {"IfBlockUnclosed", body("  if (1) { box"), "bad.grammar:5:1", "'}' to close rule A"},
        {"ComparisonChain", body("  if (1 < 2 < 3) { box }"), "bad.grammar:3:13", "comparisons do not chain"},
        {"SplitWithoutAxis", body("  split { 1: A }"), "bad.grammar:3:9", "expected an axis x, y or z after 'split'"},
        {"SplitBadAxis", body("  split w { 1: A }"), "bad.grammar:3:9", "expected an axis x, y or z after 'split', found 'w'"},
        {"SplitWithoutBraces", body("  split x 1: A"), "bad.grammar:3:11", "expected '{' after the split axis"},
        {"SplitPieceWithoutSize", body("  split x { : nil }"), "bad.grammar:3:13", "expected the size of a piece"},
        {"SplitPieceWithoutColon", body("  split x { 2 nil }"), "bad.grammar:3:15", "expected ':' after the size of a piece (SIZE: SUCCESSOR)"},
        {"SplitUnknownSuccessor", body("  split x { 2: Nowhere }"), "bad.grammar:3:16", "rule 'Nowhere' is not defined (a successor is a rule name"},
        {"SplitTwoRepeatGroups", body("  split x { { 1: nil }* | { 2: nil }* }"), "bad.grammar:3:27", "a split has at most one repeat group"},
        {"SplitGroupWithoutStar", body("  split x { { 1: nil } }"), "bad.grammar:3:24", "expected '*' after the '}' of a repeat group"},
        {"SplitMissingBar", body("  split x { 1: nil 2: nil }"), "bad.grammar:3:20", "expected '|' between the pieces of a split, or '}' to close it"},
        {"SplitSuccessorIsANumber", body("  split x { 1: 5 }"), "bad.grammar:3:16", "expected a successor: a rule name, '{ statements }' or nil"},
        {"RepeatWithoutSuccessor", body("  repeat x count 3"), "bad.grammar:4:1", "expected a successor"},
        {"CompUnknownFace", body("  comp { roof: nil }"), "bad.grammar:3:10", "unknown face 'roof': expected top, bottom, front, back, left, right or side"},
        {"CompFaceTwice", body("  comp { top: nil | top: nil }"), "bad.grammar:3:21", "face 'top' is given twice in this comp"},
        {"CompOnAFlatScope", body("  lot rect (0, 0, 1, 1) { comp { top: nil } }"), "bad.grammar:3:27", "'comp' takes a volume apart into its faces, but this scope is flat"},
        {"ExtrudeAVolume", body("  lot rect (0, 0, 1, 1) { extrude 2 extrude 3 }"), "bad.grammar:3:37", "'extrude' needs a flat scope"},
        {"CornersOnAVolume", body("  lot rect (0, 0, 1, 1) { extrude 2 corners (0.1, 0.1) nil }"), "bad.grammar:3:37", "'corners' needs a flat scope"},
        {"LotUnknownShape", body("  lot square (0, 0, 1) nil"), "bad.grammar:3:7", "unknown lot 'square': expected rect (x1, y1, x2, y2) or circle (cx, cy, r)"},
        {"LotRectTooFewNumbers", body("  lot rect (0, 0, 1) nil"), "bad.grammar:3:20", "lot rect (x1, y1, x2, y2) has 4 numbers, this gives 3"},
        {"EdgesWithoutCounts", body("  lot rect (0, 0, 1, 1) { edges (0.1, 0.1) nil }"), "bad.grammar:3:44", "expected '(' to open edges ... (n1, n2, n3, n4)"},
        {"InlineCallCycle", body("  split x { 1: B }") + "rule B { split y { 1: B } }\n", "bad.grammar:5:23", "inline calls never end: B -> B"},
        {"SplitTooManyPieces", body("  split x { " + [] {
             std::string s = "1: nil";
             for (int i = 0; i < 256; ++i) s += " | 1: nil";
             return s;
         }() + " }"), "bad.grammar:3:11", "a split lists at most 256 pieces"},
        {"InlineSelfCall", body("  A"), "bad.grammar:3:3", "inline calls never end: A -> A"},
        {"InlineArgumentsMissing", body("  split x { 1: B }") + "rule B(w) { }\n", "bad.grammar:3:16", "rule B takes 1 argument(s) (w)"},
        {"MaterialWithoutName", body("  material 5"), "bad.grammar:3:12", "expected a material name after 'material'"},
        {"LetReservedName", body("  let sin = 2"), "bad.grammar:3:7", "'sin' is a reserved name and cannot name a let value"},
        // --- expressions -----------------------------------------------------------------
        {"UnknownName", body("  translate (0, heigth, 0)"), "bad.grammar:3:17", "unknown name 'heigth'"},
        {"ParamUsedBeforeDeclared", body("  rotate x p\n  param p = uniform(0, 1)"), "bad.grammar:3:12", "unknown name 'p'"},
        {"VectorWhereScalarWanted", body("  rotate x scope.size"), "bad.grammar:3:12",
         "expected a scalar expression here, but this expression is a 3-vector"},
        {"SwizzleOnScalar", body("  param a = uniform(0, 1)\n  rotate x a.y"), "bad.grammar:4:14", "'.y' applies to a 3-vector, but this is a scalar"},
        {"SwizzleTwice", body("  rotate x scope.size.x.y"), "bad.grammar:3:25", "'.y' applies to a 3-vector, but this is a scalar"},
        {"BadComponentName", body("  rotate x scope.size.w"), "bad.grammar:3:23", "expected a component x, y or z after '.', found 'w'"},
        {"ScopeWithoutSize", body("  rotate x scope.centre.x"), "bad.grammar:3:18", "expected 'size', 'origin' or 'axis' after 'scope.', found 'centre'"},
        {"ParentWithoutDot", body("  size parent"), "bad.grammar:4:1", "expected '.' after 'parent' (only parent.size is available), found '}'"},
        {"VectorMissingComma", body("  size (1, 2 3)"), "bad.grammar:3:14",
         "expected ',' between the components of a vector (x, y, z), found number 3"},
        {"VectorWithTwoComponents", body("  size (1, 2)"), "bad.grammar:3:13",
         "expected ',' between the components of a vector (x, y, z), found ')'"},
        {"VectorComponentIsAVector", body("  size ((1, 2, 3), 1, 1)"), "bad.grammar:3:9", "a vector component must be a scalar"},
        {"UnclosedParenthesis", body("  rotate x (1 + 2"), "bad.grammar:4:1", "expected ')' to close the parenthesis, found '}'"},
        {"MissingOperand", body("  rotate x 1 +"), "bad.grammar:4:1", "expected an expression (a number, a parameter"},
        {"DanglingOperator", body("  size * 2"), "bad.grammar:3:8", "expected an expression"},
        {"FunctionWithoutParenthesis", body("  rotate x sin 30"), "bad.grammar:3:16", "expected '(' after function sin, found number 30"},
        {"FunctionTooFewArguments", body("  rotate x min(1)"), "bad.grammar:3:17", "expected ',' between the arguments of min, found ')'"},
        {"FunctionTooManyArguments", body("  rotate x abs(1, 2)"), "bad.grammar:3:17",
         "expected ')' after the 1 argument(s) of abs, found ','"},
        {"ExpressionStackTooDeep", body("  rotate x " + test::rightNested(kMaxExpressionStack)), "bad.grammar:3:12",
         "expression is too deeply nested (needs a stack of 33, the limit is 32)"},
        {"ExpressionNestingTooDeep", body("  rotate x " + std::string(100, '(') + "1" + std::string(100, ')')), "bad.grammar:3:76",
         "expression is nested too deeply (more than 64 levels"},
        {"UnaryMinusNestingTooDeep", body("  rotate x " + std::string(100, '-') + "1"), "bad.grammar:3:76", "expression is nested too deeply"},
        {"FunctionNestingTooDeep", body("  rotate x " + [] {
             std::string s;
             for (int i = 0; i < 70; ++i) s += "abs(";
             return s + "1" + std::string(70, ')');
         }()),
         "bad.grammar:3:268", "expression is nested too deeply"},
        {"ExpressionTooLong", body("  rotate x 0" + [] {
             std::string s;
             for (int i = 0; i < 3000; ++i) s += "+1";
             return s;
         }()),
         "bad.grammar:3:12", "expression is too long (more than 4096"},
    };
    return all;
}

using malformed_grammar::GrammarMalformed;

TEST_P(GrammarMalformed, IsRejectedWithLocationAndMessage) {
    const Malformed& m = GetParam();
    try {
        parseGrammar(m.text, "bad.grammar");
        FAIL() << "expected InputError for:\n" << m.text;
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(m.where + ": ", 0), 0u) << "expected location " << m.where << ", got: " << what;
        EXPECT_NE(what.find(m.fragment), std::string::npos) << "expected message fragment \"" << m.fragment << "\", got: " << what;
        EXPECT_EQ(e.file(), "bad.grammar");
    }
}

INSTANTIATE_TEST_SUITE_P(GrammarCases, GrammarMalformed, ::testing::ValuesIn(cases()), malformed_grammar::caseName);

TEST(GrammarMalformedCases, AtLeastTwentyDistinctCases) { malformed_grammar::expectTwentyDistinctCases(cases()); }

}  // namespace
}  // namespace shapevo
