// The parser's state, shared by its two files (internal to grammar/): parser.cpp reads the top
// level, rule headers, priors and child slots and instantiates rules; statements.cpp reads rule
// bodies (statements, blocks, conditionals, splits, components, lots) and inline calls.
//
// How a file is read: a first pass records every rule's header (name, arguments, where its body
// starts) and the attrs; then each rule without arguments is compiled in file order (its rule id
// is its place among them), and each rule with arguments once per distinct tuple of constant
// arguments it is called with (`child Branch(0, 120)`: an instance named "Branch(0, 120)", with
// rule ids after the plain rules, in order of first use). A rule named as a successor of a
// split, comp or lot is compiled inline into the calling rule (its parameters and slots become
// the caller gene's), once per call site.
#pragma once
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grammar/expression.hpp"
#include "grammar/grammar.hpp"
#include "grammar/lexer.hpp"
#include "grammar/parser.hpp"

namespace shapevo::grammar_detail {

/// Rule ids are 16-bit in genes; the largest |bound| of int(a, b) keeps every whole number in
/// range exactly representable as a float.
inline constexpr std::size_t kMaxRules = 65535;
inline constexpr double kMaxIntBound = 16777216.0;  // 2^24
inline constexpr int kMaxChildPositions = 64;
inline constexpr int kMaxInlineDepth = 32;
inline constexpr std::size_t kMaxStatements = 1u << 20;
inline constexpr int kMaxStatementNesting = 256;

std::string show(double v);
int axisIndex(const std::string& s);

struct RuleHeader {
    std::string name;
    SourceLocation where;
    std::vector<std::string> args;
    std::vector<SourceLocation> argWhere;
    std::size_t body = 0;                  ///< token position just after its '{'
    std::map<std::string, double> attrs;   ///< attrs defined above it
    int plainId = -1;                      ///< rule id when it takes no arguments
};

/// What the current scope is known to be while a body is compiled (for located errors such as
/// `comp` on a flat scope); Unknown where it depends on the caller.
enum class ScopeForm { Unknown, Flat, Volume };

/// The names visible in one body being compiled: its parameters (as declared there) and its
/// arguments and lets.
struct BodyScope {
    std::vector<Param> params;
    std::vector<Binding> bindings;
    const std::map<std::string, double>* attrs = nullptr;
    std::string prefix;                    ///< inline bodies: "Callee." before parameter names in Rule::params
    ScopeForm form = ScopeForm::Unknown;
};

class Parser {
public:
    Parser(const std::string& text, const std::string& path, const AttrOverrides& overrides);
    Grammar run();

    // --- parser.cpp ---
    /// A constant (attr values, prior arguments, weights, prob, max): an expression over numbers,
    /// attrs and constant arguments. Returns its dimension; vectors fill out[0..2].
    int parseConstantValue(double out[3], const std::string& what, const BodyScope* scope, bool vectorAllowed);
    double parseConstant(const std::string& what, const BodyScope* scope);
    void parseParam(Rule& rule, BodyScope& scope);
    /// uniform(a, b), int(a, b) or normal(mu, s) in [lo, hi] whose arguments depend on the scope, a parameter, a let or a
    /// run-time argument (true: read and compiled); false (nothing taken) for constant bounds.
    bool parseRunTimePrior(Rule& rule, BodyScope& scope, Param& p, const std::string& kind, const SourceLocation& at);
    void parseChild(Rule& rule, Statement& s, const SourceLocation& childAt, BodyScope& scope);
    /// The rule id for `header` called with these constant arguments (creating the instance).
    std::uint16_t instance(int header, const std::vector<Binding>& args);
    /// Arguments `( E, ... )` of a call of `header` at `at`, as bindings (constant where they fold).
    std::vector<Binding> parseArguments(int header, const SourceLocation& at, BodyScope& caller, Rule* rule,
                                        bool requireConstant);

    // --- statements.cpp ---
    /// Statements up to the closing '}' (taken), appended to rule.statements.
    void parseBlock(Rule& rule, BodyScope& scope, const std::string& closes);
    void parseStatement(Rule& rule, BodyScope& scope);
    void parseIf(Rule& rule, BodyScope& scope, const char* keyword);
    void parsePieces(Rule& rule, BodyScope& scope, const Token& word);
    /// `(E1, ..., En)` into list.arg[first, first + n) (lot, center, corners, edges).
    void parseNumberTuple(const BodyScope& scope, PieceList& list, int first, int n, const std::string& what, bool& readsScope);
    /// `comp { FACE: SUCCESSOR | ... }` after the word: one piece per face (`side`: the four sides not named).
    void parseCompFaces(Rule& rule, BodyScope& scope, const Token& word, std::vector<Piece>& pieces);
    /// `lot rect|circle (...)`, `center (...)`, `corners (...) [on (...)] [inside]`, `edges (...) (...)` after the word.
    void parseLotPieces(Rule& rule, BodyScope& scope, const Token& word, PieceList& list, std::vector<Piece>& pieces,
                        bool& readsScope);
    void parseCopy(Rule& rule, BodyScope& scope);
    /// A `[ ]` around statements about to be compiled: its Pieces statement (returns its index);
    /// closeCopy makes the statements compiled since its one piece.
    std::size_t openCopy(Rule& rule, const SourceLocation& at);
    void closeCopy(Rule& rule, std::size_t at);
    void storePieces(Rule& rule, std::size_t at, PieceList& list, std::vector<Piece>& pieces);
    /// `readsScope`: set when a piece's size reads scope.origin or scope.axis.
    void parseSplitList(Rule& rule, BodyScope& scope, std::vector<Piece>& pieces, bool& readsScope);
    void parseSuccessorList(Rule& rule, BodyScope& scope, std::vector<Piece>& pieces, ScopeForm form);
    /// One successor (a rule name with arguments: inline; `{ ... }`; `nil`): fills piece.begin/end.
    /// Successors of one statement already compiled, by name (a plain name without arguments
    /// is compiled once per statement; its pieces share the statements).
    using CompiledSuccessors = std::map<std::string, std::pair<std::uint32_t, std::uint32_t>>;
    void parseSuccessor(Rule& rule, BodyScope& scope, Piece& piece, ScopeForm form, CompiledSuccessors* compiled = nullptr);
    void inlineCall(Rule& rule, BodyScope& caller, const Token& name, ScopeForm form);
    /// Grammar::inlineCalls gains (currentRule_, name) unless it holds it.
    void recordInlineCall(const Token& name);
    void parseTerminal(Rule& rule, BodyScope& scope, const SourceLocation& at);
    std::uint16_t parseMesh();
    // --- list_statements.cpp ---
    /// A rule's body up to its closing '}' (taken): when it gathers (a scan of its tokens finds
    /// `gather` at its top level), an Open statement first, then parseBlock.
    void parseBody(Rule& rule, BodyScope& scope, const std::string& closes);
    /// Whether the body whose first token is at `body` has a `gather` at its top level.
    bool bodyGathers(std::size_t body);
    void parseSend(Rule& rule, const Token& word);
    /// `gather NAME { STEPS }` at the next token.
    void parseGather(Rule& rule, BodyScope& scope);
    /// The route that ends a gather block (after its word); successors into `op`.
    void parseRoute(Rule& rule, BodyScope& scope, const Token& word, ListOp& op);
    /// `order by E [asc|desc], ...` or `group by E, ...` (after the word): one ListOp per key.
    void parseKeys(const BodyScope& scope, const Token& word, ListOpKind kind);
    /// `raycast(±AXIS, LIST)` or `facing(LIST, DEGREES [, unoccluded])` after `let NAME =` in gather `gather`.
    void parseLookStep(const BodyScope& scope, const Token& kind, std::uint32_t gather, ListOp& op);
    std::uint16_t listName(const std::string& name, const SourceLocation& at);
    /// Rule bodies being compiled that gather, innermost last: their gathers (Grammar::gathers
    /// [first, first + tokens.size())) by the token position of their `gather` word.
    struct GatheringBody {
        std::uint32_t first = 0;
        std::vector<std::size_t> tokens;
        std::size_t next = 0;        ///< the next of them to be compiled
        std::size_t closed = 0;      ///< gathers [0, closed) are done: a route's send goes past them
    };
    std::vector<GatheringBody> bodies_;
    /// Sends no gather takes in a plain rule compiled on its own: an error only if that rule
    /// is derived as a gene (the start rule or a child slot's), found once every rule is compiled.
    struct DeferredSend {
        std::uint16_t rule;
        SourceLocation where;
        std::string message;
    };
    std::vector<DeferredSend> deferredSends_;
    bool deferSends_ = false;
    void checkDeferredSends();

    // --- texture_statement.cpp ---
    /// `texture NAME "FILE.png" (SX, SY)` after its keyword, into `s` (the image read and checked).
    void parseTexture(const BodyScope& scope, Statement& s);
    ExprRef constantExpression(float v);
    void compileScalar(const BodyScope& scope, ExprRef& out);
    void compileVector(const BodyScope& scope, ExprRef out[3]);
    /// A scalar expression that decides (if, where): a 3-vector is a located error.
    void compileCondition(const BodyScope& scope, ExprRef& out);
    std::uint16_t allocateFrame(Rule& rule, int floats, const SourceLocation& at);
    /// A frame value `name` of `dims` floats computed by expr[0..dims) at this point of the rule
    /// (a Let statement appended to it): `let`, an inline call's run-time argument, the draw of a
    /// run-time prior. Returns the (non-constant) binding that names it.
    Binding letValue(Rule& rule, const std::string& name, int dims, const ExprRef* expr, const SourceLocation& at);
    std::string statementList() const;
    /// Whether the expressions compiled since the last call read scope.origin or scope.axis
    /// (each statement's are taken just before it is appended, so they are its own).
    bool takeScopeFrameReads();
    /// A ScopeFrame statement appended to `rule` if takeScopeFrameReads(): call right before
    /// appending a statement with expressions.
    void frameScopeIfRead(Rule& rule);
    /// A ScopeFrame statement inserted at `at` (before a Pieces statement whose own expressions
    /// read the scope's frame, known once its successors are compiled): every statement index
    /// from `at` on, in `rule`, its stored piece lists and `pending` (the list's pieces), moves up one.
    void insertScopeFrame(Rule& rule, std::size_t at, std::vector<Piece>& pending);

    TokenStream tokens_;
    ExpressionCompiler exprs_;
    Grammar g_;
    std::deque<Rule> rules_;  ///< the rules while they are compiled (a deque: instances are added mid-body)
    AttrOverrides overrides_;
    std::map<std::string, double> attrs_;
    std::vector<RuleHeader> headers_;
    std::map<std::string, int> headerIndex_;
    std::map<std::string, std::uint16_t> instances_;  ///< instance name -> rule id
    struct PendingInstance {
        int header;
        std::uint16_t id;
        std::vector<Binding> args;
    };
    std::vector<PendingInstance> queue_;
    struct UndefinedRef {
        std::string name;
        SourceLocation where;
    };
    std::vector<UndefinedRef> undefined_;
    std::vector<int> inlineStack_;             ///< headers being compiled inline (cycle check)
    std::uint16_t currentRule_ = 0;            ///< the rule whose body is being compiled (Grammar::inlineCalls)
    std::optional<SourceLocation> terminalAt_;  ///< inside `terminal { }`: where it opened
    int statementDepth_ = 0;                     ///< statements being compiled inside each other (parseStatement)
    int framedReads_ = 0;                        ///< exprs_.scopeFrameReads() at the last takeScopeFrameReads()
};

}  // namespace shapevo::grammar_detail
