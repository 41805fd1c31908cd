// The `.pcg` node table (pcg_nodes.hpp): each operation's ports, arguments and shapevo text.
#include "grammar/pcg/pcg_nodes.hpp"

#include <array>


namespace shapevo::pcg {

namespace nodes_detail {

/// `STATEMENT` then what follows the only output.
template <const char* Statement>
void statementThenFlow(NodeWriter& w) {
    w.line(Statement);
    w.flow(0);
}
constexpr char kBox[] = "box", kCylinder[] = "cylinder", kSphere[] = "sphere", kParaboloid[] = "paraboloid";

void writeCone(NodeWriter& w) {
    w.line(w.arg(0).empty() ? "cone" : "cone top " + w.arg(0));
    w.flow(0);
}
void writeRoof(NodeWriter& w) {
    w.line("roof " + w.arg(0));
    w.flow(0);
}
/// `set NAME = VALUE` (PCGR's attribute mapping: a value into a carried graph attribute).
void writeSet(NodeWriter& w) {
    w.line("set " + w.arg(0) + " = " + w.arg(1));
    w.flow(0);
}
void writeExtrude(NodeWriter& w) {
    w.line("extrude " + w.arg(0));
    w.flow(0);
}
std::string vec(const NodeWriter& w) { return "(" + w.arg(0) + ", " + w.arg(1) + ", " + w.arg(2) + ")"; }
/// `STATEMENT (x, y, z)` from the first three arguments, then what follows the only output.
template <const char* Statement>
void vectorThenFlow(NodeWriter& w) {
    w.line(std::string(Statement) + " " + vec(w));
    w.flow(0);
}
constexpr char kTranslate[] = "translate", kScale[] = "scale", kSize[] = "size", kColor[] = "color";
void writeRotate(NodeWriter& w) {
    w.line("rotate " + w.arg(0) + " " + w.arg(1));
    w.flow(0);
}

/// `{` what follows output `port` `}`, or `nil`.
void successor(NodeWriter& w, std::size_t port, const std::string& before, const std::string& after) {
    if (!w.flows(port)) {
        w.line(before + "nil" + after);
        return;
    }
    w.line(before + "{");
    w.flow(port);
    w.line("}" + after);
}

void writeSplit(NodeWriter& w) {
    const std::vector<std::string>& sizes = w.sizes();
    w.line("split " + w.arg(0) + " {");
    for (std::size_t k = 0; k < sizes.size(); ++k) successor(w, k, (k ? "| " : "") + sizes[k] + ": ", "");
    w.line("}");
}

void writeRepeat(NodeWriter& w) {
    const std::string& count = w.arg(1);
    const std::string& size = w.arg(2);
    if (count.empty() == size.empty()) w.fail("repeat takes either count: N or size: SIZE (S, ~S or 'S), not both or neither");
    successor(w, 0, "repeat " + w.arg(0) + (count.empty() ? " " + size : " count " + count) + " ", "");
}

constexpr std::array<const char*, 7> kFaces{"top", "bottom", "front", "back", "left", "right", "side"};
void writeCopy(NodeWriter& w) { successor(w, 0, "copy " + w.arg(0) + " ", ""); }

void writeComp(NodeWriter& w) {
    bool any = false;
    for (std::size_t k = 0; k < kFaces.size(); ++k) any = any || w.flows(k);
    if (!any) return;  // every face a leaf: nothing follows
    w.line("comp {");
    bool first = true;
    for (std::size_t k = 0; k < kFaces.size(); ++k) {
        if (!w.flows(k)) continue;
        successor(w, k, std::string(first ? "" : "| ") + kFaces[k] + ": ", "");
        first = false;
    }
    w.line("}");
}

void writeLotRect(NodeWriter& w) {
    successor(w, 0, "lot rect (" + w.arg(0) + ", " + w.arg(1) + ", " + w.arg(2) + ", " + w.arg(3) + ") ", "");
}

void writeIf(NodeWriter& w) {
    if (!w.flows(0) && !w.flows(1)) return;  // both leaves: nothing follows either way
    w.line("if (" + w.arg(0) + ") {");
    w.flow(0);
    if (w.flows(1)) {
        w.line("} else {");
        w.flow(1);
    }
    w.line("}");
}

void writeChance(NodeWriter& w) {
    if (w.flows(0)) w.line("child " + w.childRule(0) + " prob " + w.arg(0));
}

/// `order by K1, K2 desc, ...` (each key as written, its asc / desc included).
void writeOrderBy(NodeWriter& w) {
    std::string keys;
    for (const std::string& k : w.sizes()) keys += (keys.empty() ? "" : ", ") + k;
    w.line("order by " + keys);
}
/// `group by K1, K2, ...`.
void writeGroupBy(NodeWriter& w) {
    std::string keys;
    for (const std::string& k : w.sizes()) keys += (keys.empty() ? "" : ", ") + k;
    w.line("group by " + keys);
}
void writeCluster(NodeWriter& w) { w.line("cluster " + w.arg(0) + " by " + w.arg(1)); }
void writeUnify(NodeWriter& w) { w.line(w.arg(0).empty() ? "unify" : "unify within " + w.arg(0)); }
void writeMerge(NodeWriter& w) { w.line("merge"); }
void writeUngroup(NodeWriter& w) { w.line("ungroup"); }
/// `let NAME = KIND(VALUE)`, or `let NAME = group.index`.
void writeAggregate(NodeWriter& w) {
    w.line("let " + w.arg(0) + " = " + (w.arg(1) == "group_index" ? "group.index" : w.arg(1) + "(" + w.arg(2) + ")"));
}
void writeReverse(NodeWriter& w) { w.line("reverse"); }
void writeShuffle(NodeWriter& w) { w.line("shuffle " + w.arg(0)); }
/// `keep first N [from K] : A | rest : B`, A and B what follows outputs first and rest.
void writeAmountFilter(NodeWriter& w) {
    successor(w, 0, "keep first " + w.arg(0) + (w.arg(1).empty() ? "" : " from " + w.arg(1)) + " : ", "");
    successor(w, 1, "| rest : ", "");
}
/// `where (C) : A | else : B`.
void writeFilter(NodeWriter& w) {
    successor(w, 0, "where (" + w.arg(0) + ") : ", "");
    successor(w, 1, "| else : ", "");
}

const PortSpec kVolumeIn{"in", PortType::Volume};
const PortSpec kFlatIn{"in", PortType::Flat};
const PortSpec kAnyIn{"in", PortType::Entity};
const PortSpec kVolumeOut{"out", PortType::Volume};
const PortSpec kSameOut{"out", PortType::Same};
const PortSpec kFlatOut{"out", PortType::Flat};
const PortSpec kListIn{"in", PortType::Entity, true};
const PortSpec kListOut{"out", PortType::Same, true};

const std::vector<NodeOp>& table() {
    static const std::vector<NodeOp> ops = {
        {"box", "emit a box filling the scope", {kVolumeIn}, {kVolumeOut}, {}, statementThenFlow<kBox>},
        {"cylinder", "emit a cylinder along the scope's y", {kVolumeIn}, {kVolumeOut}, {}, statementThenFlow<kCylinder>},
        {"cone", "emit a cone (top: the top radius's fraction, a frustum)", {kVolumeIn}, {kVolumeOut},
         {{"top", ArgKind::Expr, ""}}, writeCone},
        {"sphere", "emit an ellipsoid filling the scope", {kVolumeIn}, {kVolumeOut}, {}, statementThenFlow<kSphere>},
        {"paraboloid", "emit a parabolic cone", {kVolumeIn}, {kVolumeOut}, {}, statementThenFlow<kParaboloid>},
        {"roof", "emit a roof (kind: gable, hip or pyramid)", {kVolumeIn}, {kVolumeOut},
         {{"kind", ArgKind::Word, "gable", "gable hip pyramid"}}, writeRoof},
        {"extrude", "a flat scope becomes a volume standing on it", {kFlatIn}, {kVolumeOut}, {{"height", ArgKind::Expr, nullptr}},
         writeExtrude},
        {"translate", "move along the scope's axes", {kAnyIn}, {kSameOut},
         {{"x", ArgKind::Expr, "0"}, {"y", ArgKind::Expr, "0"}, {"z", ArgKind::Expr, "0"}}, vectorThenFlow<kTranslate>},
        {"rotate", "turn about the scope's own axis (degrees)", {kAnyIn}, {kSameOut},
         {{"axis", ArgKind::Axis, nullptr}, {"angle", ArgKind::Expr, nullptr}}, writeRotate},
        {"scale", "multiply the size", {kAnyIn}, {kSameOut},
         {{"x", ArgKind::Expr, "1"}, {"y", ArgKind::Expr, "1"}, {"z", ArgKind::Expr, "1"}}, vectorThenFlow<kScale>},
        {"size", "set the size (a left-out axis keeps its size)", {kAnyIn}, {kSameOut},
         {{"x", ArgKind::Expr, "scope.size.x"}, {"y", ArgKind::Expr, "scope.size.y"}, {"z", ArgKind::Expr, "scope.size.z"}},
         vectorThenFlow<kSize>},
        {"color", "the colour of what follows", {kAnyIn}, {kSameOut},
         {{"r", ArgKind::Expr, nullptr}, {"g", ArgKind::Expr, nullptr}, {"b", ArgKind::Expr, nullptr}}, vectorThenFlow<kColor>},
        {"split", "pieces along an axis, one output per size (slice1, slice2, ...)", {kAnyIn}, {},
         {{"axis", ArgKind::Axis, nullptr}, {"sizes", ArgKind::Sizes, nullptr}}, writeSplit},
        {"repeat", "equal pieces along an axis (count: N or size: S, ~S)", {kAnyIn}, {{"piece", PortType::Same}},
         {{"axis", ArgKind::Axis, nullptr}, {"count", ArgKind::Expr, ""}, {"size", ArgKind::Expr, ""}}, writeRepeat},
        {"copy", "N copies of the scope (PCGR's copy node), each telling itself apart by piece.index (0..N-1)", {kAnyIn},
         {{"out", PortType::Same}}, {{"count", ArgKind::Expr, nullptr}}, writeCopy},
        {"comp", "a volume's faces as flat scopes", {kVolumeIn},
         {{"top", PortType::Flat}, {"bottom", PortType::Flat}, {"front", PortType::Flat}, {"back", PortType::Flat},
          {"left", PortType::Flat}, {"right", PortType::Flat}, {"side", PortType::Flat}},
         {}, writeComp},
        {"lot_rect", "a rectangular lot between two corners", {kAnyIn}, {kFlatOut},
         {{"x1", ArgKind::Expr, nullptr}, {"y1", ArgKind::Expr, nullptr}, {"x2", ArgKind::Expr, nullptr}, {"y2", ArgKind::Expr, nullptr}},
         writeLotRect},
        {"if", "route to true or false by a condition", {kAnyIn}, {{"true", PortType::Same}, {"false", PortType::Same}},
         {{"condition", ArgKind::Expr, nullptr}}, writeIf, true},
        {"set", "the shape and all it derives carry value as attribute name (a `carry` of the main graph)", {kAnyIn},
         {kSameOut}, {{"name", ArgKind::Expr, nullptr}, {"value", ArgKind::Expr, nullptr}}, writeSet},
        {"chance", "go on with probability p (a constant), in a gene of its own", {kAnyIn}, {{"yes", PortType::Same}},
         {{"p", ArgKind::Expr, nullptr}}, writeChance, true, Collect::None, true},
        {"order_by", "sort the list by keys (EXPR or EXPR desc), stable", {kListIn}, {kListOut},
         {{"keys", ArgKind::Keys, nullptr}}, writeOrderBy, false, Collect::Step},
        {"reverse", "reverse the list", {kListIn}, {kListOut}, {}, writeReverse, false, Collect::Step},
        {"shuffle", "a permutation of the list drawn from u (in [0, 1])", {kListIn}, {kListOut},
         {{"u", ArgKind::Expr, nullptr}}, writeShuffle, false, Collect::Step},
        {"group_by", "group the list by keys (EXPR, ...): later steps work within each group", {kListIn}, {kListOut},
         {{"keys", ArgKind::Keys, nullptr}}, writeGroupBy, false, Collect::Step},
        {"cluster", "k groups by k-means on a point (by: EXPR, e.g. scope.origin)", {kListIn}, {kListOut},
         {{"k", ArgKind::Expr, nullptr}, {"by", ArgKind::Expr, nullptr}}, writeCluster, false, Collect::Step},
        {"unify", "group flat scopes joined by shared edges (within: the tolerance)", {kListIn}, {kListOut},
         {{"within", ArgKind::Expr, ""}}, writeUnify, false, Collect::Step},
        {"merge", "each group (or the list) becomes one entity, its bounding box", {kListIn}, {kListOut}, {}, writeMerge, false,
         Collect::Step},
        {"ungroup", "one group again", {kListIn}, {kListOut}, {}, writeUngroup, false, Collect::Step},
        {"aggregate", "name = kind(value) over the list (or each group): min, max, avg, sum, or group_index", {kListIn},
         {kListOut},
         {{"name", ArgKind::Expr, nullptr}, {"kind", ArgKind::Word, nullptr, "min max avg sum group_index"}, {"value", ArgKind::Expr, "0"}},
         writeAggregate, false, Collect::Step},
        {"amount_filter", "entities from .. from + count - 1 go to first, the others to rest", {kListIn},
         {{"first", PortType::Same, true}, {"rest", PortType::Same, true}},
         {{"count", ArgKind::Expr, nullptr}, {"from", ArgKind::Expr, ""}}, writeAmountFilter, false, Collect::Route},
        {"filter", "entities for which the condition holds go to true, the others to false", {kListIn},
         {{"true", PortType::Same, true}, {"false", PortType::Same, true}},
         {{"condition", ArgKind::Expr, nullptr}}, writeFilter, false, Collect::Route},
    };
    return ops;
}

}  // namespace nodes_detail

using namespace nodes_detail;

const char* portTypeName(PortType t) {
    switch (t) {
    case PortType::Volume: return "volume";
    case PortType::Flat: return "flat";
    case PortType::Entity: return "entity";
    case PortType::Same: return "entity";
    }
    return "?";
}

std::span<const NodeOp> nodeOps() { return table(); }

const NodeOp* findNodeOp(const std::string& name) {
    for (const NodeOp& op : table())
        if (name == op.name) return &op;
    return nullptr;
}

std::string nodeOpNames() {
    const auto& ops = table();
    std::string s;
    for (std::size_t k = 0; k < ops.size(); ++k) s += (k ? ", " : "") + std::string(ops[k].name);
    return s;
}

}  // namespace shapevo::pcg
