// parsePathData (path_data.hpp): a small scanner over SVG path grammar.
#include "graph/path_data.hpp"

#include <cctype>
#include <charconv>

#include "graph/elliptical_arc.hpp"

namespace shapevo::graph {

// Helpers in a named namespace: the unity build joins this file with others of the layer.
namespace path_data_parts {

struct Scanner {
    std::string_view s;
    std::size_t i = 0;

    void skipSeparators() {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r' || s[i] == '\f' || s[i] == ','))
            ++i;
    }
    void skipSpace() {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r' || s[i] == '\f')) ++i;
    }
    bool atNumber() {
        skipSeparators();
        if (i >= s.size()) return false;
        const char c = s[i];
        return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
    }
    /// A number per SVG's grammar: "1.5.5" is 1.5 then .5, "1-2" is 1 then -2.
    bool number(double& out) {
        skipSeparators();
        std::size_t j = i;
        if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
        const std::size_t digitsStart = j;
        while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
        if (j < s.size() && s[j] == '.') {
            ++j;
            while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
        }
        if (j == digitsStart || (j == digitsStart + 1 && s[digitsStart] == '.')) return false;
        if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
            std::size_t k = j + 1;
            if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
            if (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) {
                while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
                j = k;
            }
        }
        std::size_t from = i;
        if (s[from] == '+') ++from;
        const auto [end, ec] = std::from_chars(s.data() + from, s.data() + j, out);
        if (ec != std::errc() || end != s.data() + j) return false;
        i = j;
        return true;
    }
    /// An arc's flag: one '0' or '1', so "a1 1 0 00 1 1" has the flags 0 and 0 (SVG's grammar).
    bool flag(bool& out) {
        skipSeparators();
        if (i >= s.size() || (s[i] != '0' && s[i] != '1')) return false;
        out = s[i++] == '1';
        return true;
    }
    bool point(Vec2& p, Vec2 origin) {
        if (!number(p.x) || !number(p.y)) return false;
        p.x += origin.x;
        p.y += origin.y;
        return true;
    }
};

}  // namespace path_data_parts

PathData parsePathData(std::string_view d) {
    PathData out;
    parsePathData(d, out);
    return out;
}

void parsePathData(std::string_view d, PathData& out) {
    using namespace path_data_parts;
    out.segments.clear();
    out.complete = true;
    Scanner sc{d};
    Vec2 current, subpathStart, lastControl;
    char previous = 0;  // the previous command (upper case), for T and S reflections
    sc.skipSpace();
    char command = 0;
    while (true) {
        sc.skipSeparators();
        if (sc.i >= d.size()) break;
        const char c = d[sc.i];
        if (std::isalpha(static_cast<unsigned char>(c))) {
            command = c;
            ++sc.i;
        } else if (command == 0 || !sc.atNumber() || command == 'Z' || command == 'z') {
            out.complete = false;
            break;
        }  // else: an implicit repeat of `command`
        const bool relative = std::islower(static_cast<unsigned char>(command));
        const char op = char(std::toupper(static_cast<unsigned char>(command)));
        const Vec2 origin = relative ? current : Vec2{};
        if (out.segments.empty() && op != 'M') {  // a path starts with M
            out.complete = false;
            break;
        }
        PathSegment seg;
        bool ok = true;
        switch (op) {
        case 'M':
            ok = sc.point(seg.p[0], origin);
            if (ok) {
                seg.op = PathSegment::Op::Move;
                current = subpathStart = seg.p[0];
                command = relative ? 'l' : 'L';  // further pairs are lines
            }
            break;
        case 'L':
            ok = sc.point(seg.p[0], origin);
            seg.op = PathSegment::Op::Line;
            if (ok) current = seg.p[0];
            break;
        case 'H':
        case 'V': {
            double v = 0;
            ok = sc.number(v);
            seg.op = PathSegment::Op::Line;
            seg.p[0] = current;
            if (op == 'H') seg.p[0].x = v + (relative ? current.x : 0);
            else seg.p[0].y = v + (relative ? current.y : 0);
            if (ok) current = seg.p[0];
            break;
        }
        case 'Q':
        case 'T':
            seg.op = PathSegment::Op::Quad;
            if (op == 'Q') ok = sc.point(seg.p[0], origin) && sc.point(seg.p[1], origin);
            else {
                seg.p[0] = (previous == 'Q' || previous == 'T') ? Vec2{2 * current.x - lastControl.x, 2 * current.y - lastControl.y} : current;
                ok = sc.point(seg.p[1], origin);
            }
            if (ok) {
                lastControl = seg.p[0];
                current = seg.p[1];
            }
            break;
        case 'C':
        case 'S':
            seg.op = PathSegment::Op::Cubic;
            if (op == 'C') ok = sc.point(seg.p[0], origin) && sc.point(seg.p[1], origin) && sc.point(seg.p[2], origin);
            else {
                seg.p[0] = (previous == 'C' || previous == 'S') ? Vec2{2 * current.x - lastControl.x, 2 * current.y - lastControl.y} : current;
                ok = sc.point(seg.p[1], origin) && sc.point(seg.p[2], origin);
            }
            if (ok) {
                lastControl = seg.p[1];
                current = seg.p[2];
            }
            break;
        case 'A': {
            EllipticalArc arc;
            arc.from = current;
            ok = sc.number(arc.rx) && sc.number(arc.ry) && sc.number(arc.xAxisRotationDegrees) && sc.flag(arc.largeArc) &&
                 sc.flag(arc.sweep) && sc.point(arc.to, origin);
            if (ok) {
                appendArcSegments(arc, out.segments);  // already appended: nothing for the push below
                current = arc.to;
                previous = op;
                continue;
            }
            break;
        }
        case 'Z':
            seg.op = PathSegment::Op::Close;
            current = subpathStart;
            break;
        default: ok = false;  // an unknown command
        }
        if (!ok) {
            out.complete = false;
            break;
        }
        out.segments.push_back(seg);
        previous = op;
    }
}

}  // namespace shapevo::graph
