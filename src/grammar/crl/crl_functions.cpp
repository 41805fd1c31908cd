// CRL functions (castlemaker-crl.txt §3.7): what each becomes in the .grammar language, on the
// frame crl_translator.hpp defines (scope x = the component's X, y = its Z, z = its -Y; base at
// -size.y / 2). Each emitter writes scope statements and then calls its successors inline;
// grammars/castlemaker/README.md has the same table for users.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "grammar/crl/crl_translator.hpp"

namespace shapevo::crl {

namespace {

std::string p(const std::string& e) { return "(" + e + ")"; }

/// Scale the frame by (sx, sy) across and by h up, about the centre of its base (the thesis's
/// T * diag(sx, sy, h)).
void scaleAboutBase(Call& c, const std::string& sx, const std::string& sy, const std::string& h) {
    c.line("translate (0, scope.size.y * " + p(p(h) + " - 1") + " * 0.5, 0)");
    c.line("scale (" + sx + ", " + h + ", " + sy + ")");
}

/// Relative shares `v` of a whole: v / 100 when every share is a constant (they must add up to
/// 100), else v / (v1 + ... + vn).
std::vector<std::string> shares(Call& c, std::size_t first, std::size_t n, const char* what) {
    bool constant = true;
    double sum = 0;
    for (std::size_t k = first; k < first + n; ++k) {
        constant = constant && c.args[k].constant;
        sum += c.args[k].value;
    }
    std::vector<std::string> out;
    if (constant) {
        if (std::fabs(sum - 100.0) > 1e-3)
            c.fail(c.args[first].where, std::string("the percentages of ") + what + " add up to " + shown(sum) + ", not 100");
        for (std::size_t k = first; k < first + n; ++k) out.push_back(number(c.args[k].value / 100.0));
        return out;
    }
    std::string total;
    for (std::size_t k = first; k < first + n; ++k) total += (total.empty() ? "" : " + ") + p(c.args[k].expr);
    for (std::size_t k = first; k < first + n; ++k) out.push_back(p(c.args[k].expr) + " / " + p(total));
    return out;
}

/// `split AXIS { 'share: SUCC | ... }` over the listed shares, successors in turn.
std::string splitText(char axis, const std::vector<std::string>& parts, const std::vector<std::string>& succ) {
    std::string s = std::string("split ") + axis + " {";
    for (std::size_t k = 0; k < parts.size(); ++k) s += std::string(k ? " |" : "") + " '" + p(parts[k]) + ": " + succ[k];
    return s + " }";
}

/// How a grid's rows get their shares: constants (or attrs), expressions over the calling rule's
/// parameters, or fresh random shares per column (lot_split_rand).
enum class Rows { Constant, Caller, Random };

/// A grid of lots: columns along X with `xs` shares, rows along Y with `ys` (or `rows` random
/// ones), successors in turn x fastest from the low corner (shapevo's z runs against Y, so rows
/// are listed high Y first). A column is a helper rule shared by every column with the same
/// successors, so the successors are compiled once per column kind, not once per lot.
void grid(Call& c, const std::vector<std::string>& xs, std::vector<std::string> ys, Rows mode, int rows = 0) {
    const std::size_t nx = xs.size(), ny = mode == Rows::Random ? std::size_t(rows) : ys.size();
    auto randomShares = [&](std::size_t n) {  // each share uniform(0.25, 1), normalised
        std::vector<std::string> names, out;
        std::string total;
        for (std::size_t k = 0; k < n; ++k) {
            names.push_back(declareParam(c.t, "uniform(0.25, 1)"));
            total += (k ? " + " : "") + names.back();
        }
        for (const std::string& v : names) out.push_back(v + " / " + p(total));
        return out;
    };
    auto rowsText = [&](std::size_t ix, const std::vector<std::string>& shares) {
        std::vector<std::string> parts, succ;
        for (std::size_t r = ny; r-- > 0;) {
            parts.push_back(shares[r]);
            succ.push_back(c.succ(r * nx + ix));
        }
        return splitText('z', parts, succ);
    };
    std::vector<std::string> columns;
    for (std::size_t ix = 0; ix < nx; ++ix) {
        std::string key = "column " + std::to_string(int(mode)) + " " + std::to_string(ny);
        for (std::size_t r = 0; r < ny; ++r) key += " " + c.succ(r * nx + ix);
        if (ny == 1) columns.push_back(c.succ(ix));
        else if (mode == Rows::Caller) columns.push_back("{ " + rowsText(ix, ys) + " }");
        else {
            for (const std::string& y : ys) key += " " + y;
            columns.push_back(helperRule(c.t, key, [&] { c.line(rowsText(ix, mode == Rows::Random ? randomShares(ny) : ys)); }));
        }
    }
    if (nx == 1) {
        const std::string& only = columns[0];
        c.line(only.front() == '{' ? only.substr(2, only.size() - 4) : only);
    } else {
        c.line(splitText('x', xs, columns));
    }
}

int constantCount(Call& c, std::size_t k, int lo, int hi, const char* what) {
    const Value& v = c.args[k];
    if (!v.constant || v.value < lo || v.value > hi || v.value != std::floor(v.value))
        c.fail(v.where, std::string(what) + " must be a whole constant from " + std::to_string(lo) + " to " + std::to_string(hi) +
                            (v.constant ? ", found " + shown(v.value) : " (rand() is not allowed here)"));
    return int(v.value);
}

std::vector<std::string> equalShares(Call& c, std::size_t k) {
    const int n = constantCount(c, k, 0, 255, k == 0 ? "lot_split's number of splits in x" : "lot_split's number of splits in y") + 1;
    return std::vector<std::string>(std::size_t(n), number(1.0 / n));
}

// --- lot rules (§3.7.1) ----------------------------------------------------------------------
void rect(Call& c) {
    const auto& a = c.args;
    c.line("size (abs(" + a[2].expr + " - " + a[0].expr + "), 1, abs(" + a[3].expr + " - " + a[1].expr + "))");
    c.line("translate ((" + a[0].expr + " + " + a[2].expr + ") * 0.5, 0.5, -(" + a[1].expr + " + " + a[3].expr + ") * 0.5)");
}
void circ(Call& c) {
    const auto& a = c.args;  // the thesis's matrix scales the unit box by Radius
    c.line("size (" + a[2].expr + ", 1, " + a[2].expr + ")");
    c.line("translate (" + a[0].expr + ", 0.5, -" + p(a[1].expr) + ")");
}
void center(Call& c) {
    c.line("size (" + c.args[0].expr + ", scope.size.y, " + c.args[1].expr + ")");
    c.line(c.succ(0));
}
void corners(Call& c) {
    static const int sx[4] = {1, 1, -1, -1}, sy[4] = {-1, 1, 1, -1};  // anticlockwise from (+X, -Y)
    const std::string side = "min(" + p(c.args[0].expr) + " * scope.size.x, " + p(c.args[1].expr) + " * scope.size.z)";
    int on = 0;
    for (int k = 0; k < 4; ++k) {
        const Value& flag = c.args[2 + std::size_t(k)];
        if (flag.constant && flag.value == 0) continue;
        const std::string body = "[ translate (" + std::to_string(sx[k]) + " * scope.size.x * 0.5, 0, " + std::to_string(-sy[k]) +
                                 " * scope.size.z * 0.5) size (" + side + ", scope.size.y, " + side + ") " +
                                 c.succ(flag.constant ? std::size_t(on) : std::size_t(k)) + " ]";
        c.line(flag.constant ? body : "if (" + p(flag.expr) + " > 0.5) { " + body + " }");
        ++on;
    }
}
void edges(Call& c) {
    // Edge k anticlockwise from the -Y edge; x along the edge, the lot's Y pointing inwards.
    static const char* length[4] = {"scope.size.x", "scope.size.z", "scope.size.x", "scope.size.z"};
    static const char* across[4] = {"scope.size.z", "scope.size.x", "scope.size.z", "scope.size.x"};
    static const char* move[4] = {"(0, 0, %s)", "(%s, 0, 0)", "(0, 0, -%s)", "(-%s, 0, 0)"};
    static const int turn[4] = {0, 90, 180, 270};
    for (int k = 0; k < 4; ++k) {
        const Value& n = c.args[2 + std::size_t(k)];
        if (n.constant && n.value == 0) continue;
        const std::string inset = "(" + std::string(across[k]) + " - d__) * 0.5";
        char m[256];
        std::snprintf(m, sizeof m, move[k], inset.c_str());
        std::string s = "[ let d__ = " + p(c.args[1].expr) + " * " + across[k] + " let w__ = " + p(c.args[0].expr) + " * " +
                        length[k] + " translate " + m;
        if (turn[k]) s += " rotate y " + std::to_string(turn[k]);
        s += " size (" + std::string(length[k]) + ", scope.size.y, d__) repeat x count " + p(n.expr) +
             " { size (w__, scope.size.y, scope.size.z) " + c.succ(std::size_t(k)) + " } ]";
        c.line(s);
    }
}
void lotSplit(Call& c) {
    if (c.args.size() == 2 && (!c.args[0].constant || !c.args[1].constant)) {
        if (c.successors.size() > 1)
            c.fail(c.args[c.args[0].constant ? 1 : 0].where, "lot_split's number of splits is rand() here, which needs a single "
                                                              "successor (with several, their round robin needs constant counts)");
        // rand() counts: equal lots in a repeat along each axis (one successor: no round robin to keep)
        c.line("repeat x count " + p(c.args[0].expr) + " + 1 { repeat z count " + p(c.args[1].expr) + " + 1 " + c.succ(0) + " }");
        return;
    }
    if (c.args.size() == 2) return grid(c, equalShares(c, 0), equalShares(c, 1), Rows::Constant);
    const int dx = constantCount(c, 0, 1, 256, "lot_split's Divisions_x"), dy = constantCount(c, 1, 1, 256, "lot_split's Divisions_y");
    if (c.args.size() != std::size_t(2 + dx + dy))
        c.fail(c.app.where, "lot_split takes 2 arguments (splits in x and y) or 2 + Divisions_x + Divisions_y (" +
                                std::to_string(2 + dx + dy) + " here), this call gives " + std::to_string(c.args.size()));
    bool constantRows = true;
    for (int k = 0; k < dy; ++k) constantRows = constantRows && c.args[2 + std::size_t(dx + k)].constant;
    grid(c, shares(c, 2, std::size_t(dx), "lot_split in x"), shares(c, 2 + std::size_t(dx), std::size_t(dy), "lot_split in y"),
         constantRows ? Rows::Constant : Rows::Caller);
}
void lotSplitSimple(Call& c) {
    for (int k = 0; k < 2; ++k)
        if (c.args[std::size_t(k)].constant && !(c.args[std::size_t(k)].value >= 0 && c.args[std::size_t(k)].value <= 1))
            c.fail(c.args[std::size_t(k)].where, "lot_split_simple's fractions lie in [0, 1]");
    const std::string fx = p(c.args[0].expr), fy = p(c.args[1].expr);
    grid(c, {fx, "1 - " + fx}, {fy, "1 - " + fy}, c.args[1].constant ? Rows::Constant : Rows::Caller);
}
void lotSplitRand(Call& c);
void extrude(Call& c) {
    scaleAboutBase(c, "1", "1", c.args[0].expr);
    c.line(c.succ(0));
}
void comp(Call& c) {
    const int n = constantCount(c, 0, 3, 64, "comp's number of side faces");
    const std::size_t m = c.successors.size();
    auto side = [&](int k) { return m == 1 ? c.succ(0) : c.successors[1 + std::size_t(k) % (m - 1)]; };
    c.line("[ translate (0, scope.size.y, 0) " + c.succ(0) + " ]");  // the top: the frame moved up by its height
    auto face = [&](int k) {  // a face has unit depth, as a lot has unit height
        const std::string succ = side(k);
        return helperRule(c.t, "face " + succ, [&] { c.line("size (scope.size.x, scope.size.y, 1) " + succ); });
    };
    if (n == 4) {
        static const char* names[4] = {"front", "right", "back", "left"};  // -Y, +X, +Y, -X
        std::string s = "comp {";
        for (int k = 0; k < 4; ++k) s += std::string(k ? " |" : "") + " " + names[k] + ": " + face(k);
        c.line(s + " }");
        return;
    }
    // n sides: the faces of the n-gon around the frame's inscribed ellipse, the first facing -Y.
    const double t = std::tan(M_PI / n);
    for (int k = 0; k < n; ++k) {
        const double phi = -M_PI / 2 + 2 * M_PI * k / n, cs = std::cos(phi), sn = std::sin(phi);
        c.line("[ translate (scope.size.x * " + number(0.5 * cs) + ", 0, scope.size.z * " + number(-0.5 * sn) + ") rotate y atan2(scope.size.z * " +
               number(cs) + ", scope.size.x * " + number(-sn) + ") * 57.29577951308232 size (" + number(2 * t) + " * sqrt(scope.size.x * scope.size.x * " +
               number(0.25 * sn * sn) + " + scope.size.z * scope.size.z * " + number(0.25 * cs * cs) + "), scope.size.y, 1) " + side(k) + " ]");
    }
}
// --- subdivisions and splits ----------------------------------------------------------------
std::string countOf(std::size_t n, const char* noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); }
void subdivide(Call& c, char axis) {
    if (c.successors.size() != c.args.size())
        c.fail(c.app.where, c.app.function + " has " + countOf(c.args.size(), "percentage") + " and " + countOf(c.successors.size(), "successor") +
                                "; they must be as many");
    c.line(splitText(axis, shares(c, 0, c.args.size(), c.app.function.c_str()), c.successors));
}
void uniformSubdivide(Call& c, char axis) {
    std::string s = std::string("repeat ") + axis + " count " + p(c.args[0].expr);
    for (std::size_t k = 0; k < c.successors.size(); ++k) s += std::string(k ? " |" : "") + " " + c.successors[k];
    c.line(s);
}
void repeatSubdivide(Call& c, char axis) {
    const std::size_t n = c.args.size() - 1;
    if (c.successors.size() != n)
        c.fail(c.app.where, c.app.function + " has " + countOf(n, "percentage") + " and " + countOf(c.successors.size(), "successor") +
                                "; they must be as many");
    std::vector<std::string> parts;
    {
        Call inner{c.t, c.app, std::vector<Value>(c.args.begin() + 1, c.args.end()), c.successors, false};
        parts = shares(inner, 0, n, c.app.function.c_str());
    }
    c.line(std::string("repeat ") + axis + " count " + p(c.args[0].expr) + " { " + splitText(axis, parts, c.successors) + " }");
}
void subdiv(Call& c) { subdivide(c, 'y'); }
void uniformSubdiv(Call& c) { uniformSubdivide(c, 'y'); }
void repeatSubdiv(Call& c) { repeatSubdivide(c, 'y'); }
void split(Call& c) { subdivide(c, 'x'); }
void uniformSplit(Call& c) { uniformSubdivide(c, 'x'); }
void repeatSplit(Call& c) { repeatSubdivide(c, 'x'); }
// --- transformations and appearance ---------------------------------------------------------
void scale(Call& c) {
    scaleAboutBase(c, c.args[0].expr, c.args[1].expr, c.args[2].expr);
    c.line(c.succ(0));
}
void translate(Call& c) {
    c.line("translate (" + p(c.args[0].expr) + " * scope.size.x, " + p(c.args[2].expr) + " * scope.size.y, -" + p(c.args[1].expr) +
           " * scope.size.z)");
    c.line(c.succ(0));
}
void addMaterial(Call& c);
void addTexture(Call& c);
void insert(Call& c);
// --- terminal shapes (§3.7.3) ---------------------------------------------------------------
void insertVolume(Call& c) {
    const auto& a = c.args;
    scaleAboutBase(c, a[0].expr, a[1].expr, a[2].expr);
    const bool box = a[3].constant && a[3].value == 0 && a[4].constant && a[4].value == 0;
    const std::string solid = box ? "box" : "roof top (1 - " + p(a[3].expr) + ", 1 - " + p(a[4].expr) + ")";
    if (!a[5].constant) c.line("if (" + p(a[5].expr) + " > 0.5) { " + solid + " }");
    else if (a[5].value != 0) c.line(solid);
    if (!c.successors.empty())  // its top face, as a lot
        c.line("[ translate (0, scope.size.y, 0) size (scope.size.x * max(0, 1 - " + p(a[3].expr) + "), scope.size.y, scope.size.z * max(0, 1 - " +
               p(a[4].expr) + ")) " + c.succ(0) + " ]");
}
void insertCylinder(Call& c) {
    const auto& a = c.args;
    const std::string rb = p(a[0].expr), rt = p(a[1].expr), h = a[2].expr;
    auto narrowing = [&] {  // bottom radius rb, the top rt <= rb
        scaleAboutBase(c, rb, rb, h);
        c.line(a[0].constant && a[1].constant && a[0].value == a[1].value ? "cylinder" : "cone top " + rt + " / " + rb);
    };
    auto widening = [&] {  // upside down: the wide end on top
        scaleAboutBase(c, rt, rt, h);
        c.line("rotate z 180");
        c.line("cone top " + rb + " / " + rt);
    };
    if (a[0].constant && a[1].constant) return a[1].value <= a[0].value ? narrowing() : widening();
    c.line("if (" + rt + " <= " + rb + ") {");
    narrowing();
    c.line("} else {");
    widening();
    c.line("}");
}
void insertCone(Call& c) {
    scaleAboutBase(c, c.args[0].expr, c.args[0].expr, c.args[1].expr);
    c.line("cone");
}
void insertParabolicCone(Call& c) {
    scaleAboutBase(c, c.args[0].expr, c.args[0].expr, c.args[1].expr);
    c.line("paraboloid");
}

using A = ArgType;
const Function kFunctions[] = {
    {"rect", {A::Real, A::Real, A::Real, A::Real}, 0, false, 0, 0, rect},
    {"circ", {A::Real, A::Real, A::Real}, 0, false, 0, 0, circ},
    {"center", {A::Real, A::Real}, 0, false, 1, 1, center},
    {"corners", {A::Real, A::Real, A::Bool, A::Bool, A::Bool, A::Bool}, 0, false, 1, -1, corners},
    {"edges", {A::Real, A::Real, A::Int, A::Int, A::Int, A::Int}, 0, false, 1, -1, edges},
    {"lot_split", {A::Int, A::Int, A::Real}, 1, true, 1, -1, lotSplit},
    {"lot_split_simple", {A::Real, A::Real}, 0, false, 1, 4, lotSplitSimple},
    {"lot_split_rand", {A::Int, A::Int}, 0, false, 1, -1, lotSplitRand},
    {"extrude", {A::Real}, 0, false, 1, 1, extrude},
    {"comp", {A::Int}, 0, false, 1, -1, comp},
    {"subdiv", {A::Real}, 0, true, 1, -1, subdiv},
    {"uniform_subdiv", {A::Int}, 0, false, 1, -1, uniformSubdiv},
    {"repeat_subdiv", {A::Int, A::Real}, 0, true, 1, -1, repeatSubdiv},
    {"split", {A::Real}, 0, true, 1, -1, split},
    {"uniform_split", {A::Int}, 0, false, 1, -1, uniformSplit},
    {"repeat_split", {A::Int, A::Real}, 0, true, 1, -1, repeatSplit},
    {"scale", {A::Real, A::Real, A::Real}, 0, false, 1, 1, scale},
    {"translate", {A::Real, A::Real, A::Real}, 0, false, 1, 1, translate},
    {"add_material", {A::String, A::Real, A::Real, A::Real}, 0, false, 1, 1, addMaterial},
    {"add_texture", {A::String, A::String, A::Real, A::Real}, 0, false, 1, 1, addTexture},
    {"insert", {A::String, A::Bool, A::Bool, A::Bool}, 3, false, 0, 0, insert},
    {"insert_volume", {A::Real, A::Real, A::Real, A::Real, A::Real, A::Bool}, 0, false, 0, 1, insertVolume},
    {"insert_cylinder", {A::Real, A::Real, A::Real, A::Int}, 0, false, 0, 0, insertCylinder},
    {"insert_cone", {A::Real, A::Real, A::Int}, 0, false, 0, 0, insertCone},
    {"insert_parabolic_cone", {A::Real, A::Real, A::Int, A::Int}, 0, false, 0, 0, insertParabolicCone},
};

void lotSplitRand(Call& c) {
    const int nx = constantCount(c, 0, 0, 255, "lot_split_rand's number of splits in x") + 1;
    const int ny = constantCount(c, 1, 0, 255, "lot_split_rand's number of splits in y") + 1;
    std::vector<std::string> xs, names;
    std::string total;
    for (int k = 0; k < nx && nx > 1; ++k) {  // each column's share uniform(0.25, 1), normalised
        names.push_back(declareParam(c.t, "uniform(0.25, 1)"));
        total += (k ? " + " : "") + names.back();
    }
    for (const std::string& v : names) xs.push_back(v + " / " + p(total));
    if (nx == 1) xs.push_back("1");
    grid(c, xs, ny == 1 ? std::vector<std::string>{"1"} : std::vector<std::string>{}, ny == 1 ? Rows::Constant : Rows::Random, ny);
}
bool isMaterialWord(const std::string& s) {
    if (s.empty()) return false;
    for (char ch : s)
        if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-' || ch == '.')) return false;
    return true;
}
void addMaterial(Call& c) {
    if (!isMaterialWord(c.args[0].text))
        c.fail(c.args[0].where, "a material handle is letters, digits, '_', '-' and '.', found \"" + c.args[0].text + "\"");
    if (looks(c.t) == Looks::Keep) {
        c.line("material \"" + materialName(c.t, c.args[0].text) + "\"");
        c.line("color (" + c.args[1].expr + ", " + c.args[2].expr + ", " + c.args[3].expr + ")");
    }
    c.line(c.succ(0));
}
void addTexture(Call& c) {
    if (!isMaterialWord(c.args[0].text))
        c.fail(c.args[0].where, "a texture handle is letters, digits, '_', '-' and '.', found \"" + c.args[0].text + "\"");
    const std::string file = fileFor(c.t, c.args[1].where, c.args[1].text, "texture");
    if (looks(c.t) == Looks::Keep)
        c.line("texture \"" + materialName(c.t, c.args[0].text) + "\" \"" + file + "\" (" + c.args[2].expr + ", " + c.args[3].expr + ")");
    c.line(c.succ(0));
}
void insert(Call& c) {
    const auto& a = c.args;
    auto flag = [&](std::size_t k) {
        if (k >= a.size()) return false;
        if (!a[k].constant) c.fail(a[k].where, "insert's flags are constants 0 or 1 (rand() is not allowed here)");
        return a[k].value != 0;
    };
    const bool textured = flag(1), local = flag(2), keepHeight = flag(3);
    const std::string& name = a[0].text;
    const bool ruleFile = name.size() > 5 && name.compare(name.size() - 5, 5, ".rule") == 0;
    const std::string file = fileFor(c.t, a[0].where, name, ruleFile ? "rule file" : "OBJ");
    if (keepHeight) {  // not_scale_z: the object keeps its own height
        const std::string h = number(ruleFile ? 1.0 : objectHeight(c.t, a[0].where, file));
        c.line("translate (0, (" + h + " - scope.size.y) * 0.5, 0) size (scope.size.x, " + h + ", scope.size.z)");
    }
    if (textured && !ruleFile) c.line("color (0.8, 0.8, 0.8) material \"\"");  // its own look: shapevo's default
    if (ruleFile) {
        c.line(insertedModel(c.t, a[0].where, file, textured, local));
        return;
    }
    // An OBJ stands upright with Z up (§3.7.2): its z fills the frame's height, its y the depth.
    c.line("rotate x -90 size (scope.size.x, scope.size.z, scope.size.y) mesh \"" + file + "\"");
}

}  // namespace

std::string shown(double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.9g", v);
    return b;
}
std::string number(double v) { return v < 0 ? "(" + shown(v) + ")" : shown(v); }

const Function* findFunction(const std::string& name) {
    for (const Function& f : kFunctions)
        if (name == f.name) return &f;
    return nullptr;
}

std::string similarFunction(const std::string& name) {
    if (name.size() > 64) return "";
    std::string best;
    std::size_t bestDistance = 3;
    for (const Function& f : kFunctions) {  // Levenshtein distance, one row at a time
        const std::string w = f.name;
        std::vector<std::size_t> row(w.size() + 1);
        for (std::size_t j = 0; j <= w.size(); ++j) row[j] = j;
        for (std::size_t i = 1; i <= name.size(); ++i) {
            std::size_t diagonal = row[0];
            row[0] = i;
            for (std::size_t j = 1; j <= w.size(); ++j) {
                const std::size_t up = row[j];
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (name[i - 1] == w[j - 1] ? 0 : 1)});
                diagonal = up;
            }
        }
        if (row[w.size()] < bestDistance) bestDistance = row[w.size()], best = w;
    }
    return best;
}

std::string functionNames() {
    std::string s;
    for (const Function& f : kFunctions) s += (s.empty() ? "" : ", ") + std::string(f.name);
    return s;
}

}  // namespace shapevo::crl
