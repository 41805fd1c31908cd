// What the grammar fuzz targets (fuzz_grammar_parser.cpp, fuzz_rule_parser.cpp) check: an
// InputError must be located inside the text it blames, and every grammar parseGrammar accepts
// must keep the invariants derivation relies on. A broken check aborts (a crash to libFuzzer).
#pragma once
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>

#include "base/input_error.hpp"
#include "grammar/expression.hpp"
#include "grammar/front_ends.hpp"

namespace shapevo::fuzz {

[[noreturn]] inline void broken(const char* what) {
    std::fprintf(stderr, "fuzz target: invariant broken: %s\n", what);
    std::abort();
}
#define FUZZ_CHECK(cond)                              \
    do {                                              \
        if (!(cond)) ::shapevo::fuzz::broken(#cond);  \
    } while (0)

/// An error must start with "FILE:LINE:COL: " and point inside `text`, FILE's text (or just past
/// its end). Lines count from 1; columns count bytes (or characters, which are never more) from 1,
/// and may be one past the line's last byte.
inline void checkLocated(const InputError& e, const std::string& text, const std::string& file) {
    const std::string what = e.what();
    const std::string prefix = shortened(file, 256) + ":";
    FUZZ_CHECK(e.file() == file && what.rfind(prefix, 0) == 0);
    int line = 0, column = 0, consumed = 0;
    FUZZ_CHECK(std::sscanf(what.c_str() + prefix.size(), "%d:%d: %n", &line, &column, &consumed) == 2 && consumed > 0);
    FUZZ_CHECK(what.size() > prefix.size() + std::size_t(consumed));  // a message follows the location
    int l = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < text.size() && l < line; ++i)
        if (text[i] == '\n') {
            ++l;
            lineStart = i + 1;
        }
    FUZZ_CHECK(line >= 1 && l == line);
    std::size_t lineEnd = text.find('\n', lineStart);
    if (lineEnd == std::string::npos) lineEnd = text.size();
    FUZZ_CHECK(column >= 1 && std::size_t(column) <= lineEnd - lineStart + 1);
}

inline void checkAccepted(const Grammar& g) {
    FUZZ_CHECK(!g.rules.empty() && g.start < g.rules.size());
    FUZZ_CHECK(g.maxStack >= 0 && g.maxStack <= kMaxExpressionStack);
    FUZZ_CHECK(g.mandatoryGenes.size() == g.rules.size() && g.mandatoryWords.size() == g.rules.size());
    std::set<std::uint32_t> edges;
    for (std::size_t r = 0; r < g.rules.size(); ++r) {
        const Rule& rule = g.rules[r];
        FUZZ_CHECK(g.mandatoryGenes[r] >= 1 && g.mandatoryGenes[r] <= 1000000);
        FUZZ_CHECK(g.mandatoryWords[r] >= rule.geneWords());
        FUZZ_CHECK(rule.childOffsets <= 64 && rule.paramFloats <= 256);
        std::uint32_t offsets = 0;
        for (const Slot& s : rule.slots) {
            FUZZ_CHECK(!s.rules.empty() && s.rules.size() == s.weights.size());
            float totalWeight = 0;
            for (std::size_t a = 0; a < s.rules.size(); ++a) {
                FUZZ_CHECK(s.rules[a] < g.rules.size());
                FUZZ_CHECK(s.weights[a] > 0 && std::isfinite(s.weights[a]));
                totalWeight += s.weights[a];
            }
            FUZZ_CHECK(std::isfinite(totalWeight));
            FUZZ_CHECK(s.probability >= 0 && s.probability <= 1);
            FUZZ_CHECK(s.maxCount >= 1 && s.firstChild == offsets);
            offsets += s.maxCount;
            FUZZ_CHECK(s.edge < g.edgeCount && edges.insert(s.edge).second);
        }
        FUZZ_CHECK(offsets == rule.childOffsets);
        std::uint32_t floats = 0;
        for (const Param& p : rule.params) {
            FUZZ_CHECK(p.first == floats && (p.dims == 1 || p.dims == 3));
            floats += p.dims;
            for (int c = 0; c < p.dims; ++c) {
                const Prior& pr = p.prior[c];
                FUZZ_CHECK(std::isfinite(pr.lo) && std::isfinite(pr.hi) && pr.lo <= pr.hi);
                if (pr.kind == PriorKind::Normal) FUZZ_CHECK(pr.sigma > 0 && std::isfinite(pr.mu));
                if (pr.kind == PriorKind::Int) FUZZ_CHECK(std::ceil(pr.lo) <= std::floor(pr.hi));
                if (pr.kind == PriorKind::Choice)
                    FUZZ_CHECK(pr.choiceCount >= 1 && pr.choiceBegin + pr.choiceCount <= g.choiceValues.size());
            }
        }
        FUZZ_CHECK(floats == rule.paramFloats);
        // Every compiled expression stays inside the code and evaluates within the stack limit
        // (AddressSanitizer catches a push past the end of `stack`); parameter reads stay in the
        // stored block or in the rule's frame values.
        // The block derive evaluates with: stored floats, frame values, then the piece key that
        // `per piece` parameters (OpCode::Fresh) read.
        float params[kParamBlockFloats], scope[3] = {1, 2, 3}, parent[3] = {4, 5, 6};
        for (std::size_t i = kPieceIndexSlot; i < kParamBlockFloats; ++i) params[i] = 0.25f * float(i);
        for (std::size_t i = 0; i < kPieceKeySlot; ++i) params[i] = 0.5f + float(i);
        const std::uint32_t pieceKey = 12345;
        std::memcpy(&params[kPieceKeySlot], &pieceKey, sizeof pieceKey);
        FUZZ_CHECK(rule.frameFloats <= kFrameBase);
        auto checkExpression = [&](const ExprRef& e) {
            FUZZ_CHECK(e.begin < e.end && e.end <= g.code.size());
            for (std::uint32_t i = e.begin; i < e.end; ++i) {
                if (g.code[i].op == OpCode::Param)
                    FUZZ_CHECK(g.code[i].index < rule.paramFloats ||
                          (g.code[i].index >= kFrameBase && g.code[i].index < kFrameBase + rule.frameFloats) ||
                          (g.code[i].index >= kPieceIndexSlot && g.code[i].index < kParamBlockFloats));
                if (g.code[i].op == OpCode::ScopeSize || g.code[i].op == OpCode::ParentSize) FUZZ_CHECK(g.code[i].component < 3);
            }
            float stack[kMaxExpressionStack];
            (void)evaluate(g, e, params, scope, parent, stack);
        };
        const std::size_t count = rule.statements.size();
        for (std::size_t index = 0; index < count; ++index) {
            const Statement& st = rule.statements[index];
            int n = 0;
            switch (st.kind) {
            case StatementKind::Rotate: case StatementKind::If: case StatementKind::Extrude: case StatementKind::Set: n = 1; break;
            case StatementKind::Primitive:  // a kind's arguments (cone top, roof top (x, z)): those it set
                for (const ExprRef& e : st.expr)
                    if (e.end > e.begin) checkExpression(e);
                break;
            case StatementKind::Scale: case StatementKind::Size: case StatementKind::Translate: case StatementKind::Color: n = 3; break;
            case StatementKind::Let: n = st.axis; break;
            case StatementKind::Texture: n = 2; break;
            default: break;
            }
            if (st.kind == StatementKind::Child) FUZZ_CHECK(st.slot < rule.slots.size());
            if (st.kind == StatementKind::Set) FUZZ_CHECK(st.slot < g.carriedNames.size());
            if (st.kind == StatementKind::Primitive && st.primitive == PrimitiveKind::Mesh) FUZZ_CHECK(st.slot < g.meshes.size());
            if (st.kind == StatementKind::TerminalBegin) FUZZ_CHECK(st.end < count && rule.statements[st.end].kind == StatementKind::TerminalEnd);
            if (st.kind == StatementKind::Rotate || st.kind == StatementKind::Mirror) FUZZ_CHECK(st.axis < 3);
            if (st.kind == StatementKind::If || st.kind == StatementKind::Jump || st.kind == StatementKind::Pieces)
                FUZZ_CHECK(st.end > index && st.end <= count);  // forward jumps only: derive always ends
            if (st.kind == StatementKind::Let)
                FUZZ_CHECK((st.axis == 1 || st.axis == 3) && st.slot >= kFrameBase && st.slot + st.axis <= kFrameBase + rule.frameFloats);
            if (st.kind == StatementKind::Material) FUZZ_CHECK(st.slot < g.materialNames.size());
            if (st.kind == StatementKind::Texture)
                FUZZ_CHECK(st.slot < g.textures.size() && g.textures[st.slot].material < g.materialNames.size() &&
                           !g.textures[st.slot].png.empty() && g.hasAppearance);
            if (st.kind == StatementKind::Pieces) {
                FUZZ_CHECK(st.slot < g.pieceLists.size());
                const PieceList& list = g.pieceLists[st.slot];
                FUZZ_CHECK(list.count >= 1 && list.first + list.count <= g.pieces.size() && list.axis < 3);
                for (const ExprRef& e : list.arg)
                    if (e.end > e.begin) checkExpression(e);
                for (std::uint32_t k = 0; k < list.count; ++k) {
                    const Piece& piece = g.pieces[list.first + k];
                    FUZZ_CHECK(piece.begin > index && piece.begin <= piece.end && piece.end <= st.end);
                    FUZZ_CHECK(piece.face < kFaces);
                    if (list.kind == PiecesKind::Split) checkExpression(piece.value);
                }
            }
            if (st.kind == StatementKind::Open) FUZZ_CHECK(g.hasLists && st.end >= 1 && st.slot + st.end <= g.gathers.size());
            if (st.kind == StatementKind::Send) FUZZ_CHECK(st.slot < g.listNames.size());
            if (st.kind == StatementKind::Gather) {  // its steps' expressions and its route's successors (after it, up to its end)
                FUZZ_CHECK(st.slot < g.gathers.size() && st.end > index && st.end <= count);
                const Gather& gather = g.gathers[st.slot];
                FUZZ_CHECK(gather.list < g.listNames.size() && gather.ops >= 1 && gather.firstOp + gather.ops <= g.listOps.size());
                for (std::uint32_t k = 0; k < gather.ops; ++k) {
                    const ListOp& op = g.listOps[gather.firstOp + k];
                    const bool route = op.kind == ListOpKind::KeepFirst || op.kind == ListOpKind::Each || op.kind == ListOpKind::Where;
                    FUZZ_CHECK(route == (k + 1 == gather.ops));
                    for (int e = 0; e < listOpExpressions(op); ++e) checkExpression(op.expr[e]);
                    if (op.kind == ListOpKind::OrderBy || op.kind == ListOpKind::GroupBy) FUZZ_CHECK(op.keys >= 1);
                    if (op.kind == ListOpKind::Cluster) FUZZ_CHECK(op.dims == 1 || op.dims == 3);
                    if (op.kind == ListOpKind::RayCast || op.kind == ListOpKind::Facing)
                        FUZZ_CHECK(op.slot >= kFrameBase && op.slot + 1 <= kFrameBase + rule.frameFloats &&
                                   (op.other == kOwnList || op.other < g.gathers.size()));
                    if (op.kind == ListOpKind::Aggregate)
                        FUZZ_CHECK((op.dims == 1 || op.dims == 3) && op.detail <= std::uint8_t(AggregateKind::GroupIndex) && op.slot >= kFrameBase &&
                                   op.slot + op.dims <= kFrameBase + rule.frameFloats);
                    if (route)
                        for (int r = 0; r < 2; ++r) FUZZ_CHECK(op.begin[r] > index && op.begin[r] <= op.end[r] && op.end[r] <= st.end);
                }
            }
            for (int c = 0; c < n; ++c) checkExpression(st.expr[c]);
        }
    }
}

}  // namespace shapevo::fuzz
