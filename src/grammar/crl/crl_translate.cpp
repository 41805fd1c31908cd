// CRL translation: rule files (with their includes and inserted rule files) -> the text of one
// .grammar file, line by line with the rule-file place each line came from.
//
// How rules map (grammars/castlemaker/README.md has the user's view):
//  - every handle is a rule of the same name; a successor is an inline call of it, so a model's
//    deterministic part is one gene and every rand() in it an evolvable parameter of that gene;
//  - several rules with the same predecessor all apply to the same component: each but the last
//    runs in a `[ ]` block (a copy of the scope);
//  - a stochastic rule `[p] f(...), [q] g(...)` is an alternative drawn from a `per piece`
//    parameter (`case (pick < p) { f } else { g }`), so that every piece of a split draws its own
//    alternative as in CastleMaker; one that leads back to its own predecessor (recursion, §5.2)
//    is an `optional` child slot `child [p] A1 | [q] A2 optional` instead, a gene per step;
//  - every rand(a, b) is `param ... = uniform(a, b) per piece` (int(a, b) for whole numbers):
//    the first piece of a kind uses the gene's value, the others draw their own from it;
//  - the start rule runs every direct lot (`L = rect(...)`) in its own block.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/input_error.hpp"
#include "grammar/crl/crl_translator.hpp"
#include "mesh/mesh_reader.hpp"

namespace shapevo::crl {

namespace fs = std::filesystem;

namespace {
std::string at(const Location& l) { return std::to_string(l.line) + ":" + std::to_string(l.column); }
[[noreturn]] void failAt(const Location& l, const std::string& what) { throw InputError(l.file, at(l), what); }

/// The text of the rule file `path`, named `written` (as the rule file wrote it) at `from` if it cannot be read.
std::string readText(const std::string& path, const Location& from, const char* what, const std::string& written) {
    std::error_code ec;
    std::ifstream in;
    if (fs::is_regular_file(path, ec)) in.open(path, std::ios::binary);  // never a folder, a device or a pipe
    if (!in.is_open() || !in)
        failAt(from, std::string("cannot open ") + what + " '" + shortened(written) + "' (looked for " + shortened(path, 200) + ")");
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
}  // namespace

/// One rule file with its includes, translated under a prefix (an inserted model's handles and
/// attrs are kept apart from its includer's).
struct Unit {
    std::string prefix;
    Looks looks = Looks::Keep;
    bool sharedMaterials = true;
    std::deque<File> files;
    std::vector<const Attr*> attrs;
    std::map<std::string, double> attrValue;
    std::map<std::string, std::vector<const RuleDef*>> handles;
    std::vector<std::string> order;
    std::vector<const RuleDef*> lots;
};

class Translator {
public:
    Translator(const std::string& mainPath, const std::map<std::string, double>& overrides, Translation& out)
        : mainDir_(fs::path(mainPath).parent_path()), overrides_(overrides), out_(out) {}

    void run(const std::string& text, const std::string& path) {
        Unit& u = units_.emplace_back();
        inserting_.push_back(fs::weakly_canonical(fs::path(path)).string());  // an inserted file may insert this one
        insertingNames_.push_back(fs::path(path).filename().generic_string());
        load(u, text, path, nullptr);
        for (const auto& [name, v] : overrides_)
            if (u.attrValue.count(name)) u.attrValue[name] = v;
        emitUnit(u);
        if (u.lots.empty()) throw InputError(path, "1:1", "no lot: a rule file needs a direct lot (Handle = rect(x1, y1, x2, y2); or circ(cx, cy, r);)");
        begin("crl__model", Location{path, 1, 1});
        for (const RuleDef* d : u.lots) {
            cur_->push_back({d->where, "["});
            emitApplication(u, d->alternatives[0], true);
            cur_->push_back({d->where, u.prefix + d->predecessor});
            cur_->push_back({d->where, "]"});
        }
        end();
        for (const Attr* a : u.attrs) write({a->where, "attr " + u.prefix + a->name + " = " + number(a->value)});
        for (const Line& l : attrLines_) write(l);
        write({Location{path, 1, 1}, "start crl__model"});
        for (const Line& l : rulesText_) write(l);
    }

    // --- what emitters ask for ---------------------------------------------------------------
    std::string declareParam(const std::string& prior) {
        const std::string name = "rand__" + std::to_string(++params_);
        cur_->push_back({where_, "param " + name + " = " + prior + " per piece"});
        return name;
    }
    std::string fileFor(const Location& from, const std::string& file, const char* what) {
        const fs::path full = fs::path(from.file).parent_path() / file;
        std::error_code ec;
        if (!fs::is_regular_file(full, ec)) failAt(from, std::string("cannot open ") + what + " '" + shortened(file) + "' (looked for " + shortened(full.string(), 200) + ")");
        return full.lexically_normal().lexically_relative(mainDir_.empty() ? fs::path(".") : mainDir_).generic_string();
    }
    double objectHeight(const Location& from, const std::string& file) {
        try {
            const Mesh m = readMesh((mainDir_ / file).string());
            float lo = INFINITY, hi = -INFINITY;
            for (const auto& v : m.vertices) {
                lo = std::min(lo, v.z);
                hi = std::max(hi, v.z);
            }
            return hi > lo ? hi - lo : 1.0;
        } catch (const InputError& e) {
            failAt(from, "OBJ '" + shortened(file) + "': " + e.message());
        }
    }
    std::string insertedModel(const Location& from, const std::string& file, bool textured, bool local) {
        const std::string key = file + (textured ? "#t" : "#-") + (local ? "l" : "-");
        const std::string canonical = fs::weakly_canonical(mainDir_ / file).string();
        if (std::find(inserting_.begin(), inserting_.end(), canonical) != inserting_.end()) {
            std::string chain;
            for (auto it = std::find(inserting_.begin(), inserting_.end(), canonical); it != inserting_.end(); ++it)
                chain += insertingNames_[std::size_t(it - inserting_.begin())] + " -> ";
            failAt(from, "insert cycle: " + chain + shortened(file) + " (rule files that insert each other never end)");
        }
        if (auto it = models_.find(key); it != models_.end()) return it->second;
        const std::string prefix = "I" + std::to_string(models_.size() + 1) + "__";
        models_[key] = prefix + "model";
        Unit& u = units_.emplace_back();
        u.prefix = prefix;
        u.looks = textured ? Looks::Keep : Looks::Drop;
        u.sharedMaterials = local;
        inserting_.push_back(canonical);
        insertingNames_.push_back(file);
        const std::string path = (mainDir_ / file).generic_string();
        load(u, readText(path, from, "inserted rule file", file), path, &from);
        for (const Attr* a : u.attrs) attrLines_.push_back({a->where, "attr " + u.prefix + a->name + " = " + number(a->value)});
        std::vector<Line>* saved = cur_;
        const Location savedWhere = where_;
        Unit* savedUnit = unit_;
        emitUnit(u);
        modelRule(u, from);
        cur_ = saved;
        where_ = savedWhere;
        unit_ = savedUnit;
        inserting_.pop_back();
        insertingNames_.pop_back();
        return models_[key];
    }
    std::string helper(const std::string& key, const std::function<void()>& body) {
        const std::string full = unit_->prefix + key;
        if (auto it = helpers_.find(full); it != helpers_.end()) return it->second;
        const std::string name = unit_->prefix + "crl__h" + std::to_string(helpers_.size() + 1);
        helpers_[full] = name;
        const Location where = where_;
        begin(name, where);
        body();
        end();
        where_ = where;
        return name;
    }
    Looks looks() const { return unit_->looks; }
    std::string materialName(const std::string& name) const { return unit_->sharedMaterials ? name : unit_->prefix + name; }
    void line(const std::string& s) { cur_->push_back({where_, s}); }

private:
    struct Line {
        Location where;
        std::string text;
    };

    void write(const Line& l) {
        out_.text += l.text;
        out_.text += '\n';
        out_.origin.push_back(l.where);
    }

    // --- files and includes ------------------------------------------------------------------
    void load(Unit& u, const std::string& text, const std::string& path, const Location* from) {
        const std::string canonical = fs::weakly_canonical(fs::path(path)).string();
        if (std::find(stack_.begin(), stack_.end(), canonical) != stack_.end()) {
            std::string chain;
            for (const std::string& s : stack_) chain += fs::path(s).filename().string() + " -> ";
            failAt(*from, "include cycle: " + chain + fs::path(path).filename().string());
        }
        stack_.push_back(canonical);
        if (!u.files.empty() || from) {
            const std::string rel = fs::path(path).lexically_relative(mainDir_.empty() ? fs::path(".") : mainDir_).generic_string();
            if (std::find(out_.files.begin(), out_.files.end(), rel) == out_.files.end()) out_.files.push_back(rel);
        }
        u.files.push_back(readCrl(text, path));
        const File& f = u.files.back();
        for (const Attr& a : f.attrs) {
            if (a.name.find("__") != std::string::npos)
                failAt(a.where, "attr names with '__' are kept for shapevo's own names");
            if (u.attrValue.count(a.name)) failAt(a.where, "attr '" + a.name + "' is defined twice");
            static const char* reserved[] = {"scope", "parent", "pi", "min", "max", "abs", "sin", "cos", "sqrt", "floor", "atan2"};
            for (const char* r : reserved)
                if (a.name == r) failAt(a.where, "'" + a.name + "' is a reserved name in shapevo and cannot name an attr");
            u.attrValue[a.name] = a.value;
            u.attrs.push_back(&a);
        }
        for (const Include& inc : f.includes) {
            const std::string child = (fs::path(path).parent_path() / inc.path).generic_string();
            load(u, readText(child, inc.where, "included rule file", inc.path), child, &inc.where);
        }
        for (const RuleDef& r : f.rules) {
            if (r.predecessor.find("__") != std::string::npos)
                failAt(r.where, "handles with '__' are kept for shapevo's own names");
            if (!u.handles.count(r.predecessor)) u.order.push_back(r.predecessor);
            u.handles[r.predecessor];
            if (r.direct) u.lots.push_back(&r);
            else u.handles[r.predecessor].push_back(&r);
        }
        stack_.pop_back();
    }

    // --- checks and the handle graph ---------------------------------------------------------
    static bool stochastic(const RuleDef& d) { return d.alternatives.size() > 1 || d.alternatives[0].weighted; }

    void check(const Unit& u, const Application& app, bool direct) {
        const Function* f = findFunction(app.function);
        if (!f) {
            const std::string near = similarFunction(app.function);
            failAt(app.where, "unknown function '" + shortened(app.function) + "'" + (near.empty() ? "" : " (did you mean " + near + "?)") +
                                  ": expected one of " + functionNames());
        }
        const bool lot = app.function == "rect" || app.function == "circ";
        if (direct && !lot) failAt(app.where, "a direct rule (Handle = ...) makes a lot with rect(x1, y1, x2, y2) or circ(cx, cy, r), not " + app.function);
        if (!direct && lot) failAt(app.where, app.function + " makes a direct lot: write Handle = " + app.function + "(...);");
        const std::size_t n = app.args.size(), T = f->args.size();
        const std::size_t lo = T - std::size_t(f->optionalArgs);
        if (n < lo || (!f->variadic && n > T)) {
            std::string want = f->variadic ? "at least " + std::to_string(lo) : lo == T ? std::to_string(T) : std::to_string(lo) + " to " + std::to_string(T);
            failAt(app.where, app.function + " takes " + want + " argument" + (lo == 1 && (T == 1 || f->variadic) ? "" : "s") + ", this call gives " + std::to_string(n));
        }
        const int s = int(app.successors.size());
        if (s < f->minSuccessors)
            failAt(app.where, app.function + " needs " + (f->minSuccessors == 1 ? "a successor {Handle}" : std::to_string(f->minSuccessors) + " successors"));
        if (f->maxSuccessors >= 0 && s > f->maxSuccessors)
            failAt(app.successors[std::size_t(f->maxSuccessors)].where,
                   app.function + (lot ? " makes a lot, which takes no successor: its rules follow as Handle -> function(...) {...};"
                                   : f->maxSuccessors == 0 ? " is a terminal and takes no successor" : " takes at most " + std::to_string(f->maxSuccessors) + " successor" + (f->maxSuccessors == 1 ? "" : "s")));
        for (const Successor& sc : app.successors)
            if (!u.handles.count(sc.handle)) failAt(sc.where, "handle '" + shortened(sc.handle) + "' is never defined (no rule " + shortened(sc.handle) + " -> ...; and no lot " + shortened(sc.handle) + " = ...;)");
    }

    void checkStochastic(const RuleDef& d) {
        double sum = 0;
        for (const Application& a : d.alternatives) {
            if (!a.weighted) failAt(a.where, "every alternative of a stochastic rule has a probability: [p] " + a.function + "(...)");
            if (!(a.probability >= 0 && a.probability <= 1)) failAt(a.probabilityAt, "a probability lies in [0, 1], found " + shown(a.probability));
            sum += a.probability;
        }
        if (std::fabs(sum - 1.0) > 1e-4)
            failAt(d.alternatives[0].probabilityAt, "the probabilities of this stochastic rule add up to " + shown(sum) + ", not 1 (castlemaker-crl.txt §3.7.4)");
    }

    /// Which stochastic rules lead back to their own predecessor (they become child slots), and
    /// that no cycle is left among the rules called inline.
    void analyse(Unit& u) {
        // Both walks keep their own stacks: a chain of 100,000 handles must not overflow the C++ stack.
        const std::size_t n = u.order.size();
        std::map<std::string, int> id;
        for (std::size_t v = 0; v < n; ++v) id[u.order[v]] = int(v);
        std::vector<std::vector<const Successor*>> next(n), inlineNext(n);  // every successor; those called inline
        std::vector<std::vector<const RuleDef*>> stochasticDefs(n);
        for (std::size_t v = 0; v < n; ++v)
            for (const RuleDef* d : u.handles[u.order[v]]) {
                if (stochastic(*d)) stochasticDefs[v].push_back(d);
                for (const Application& a : d->alternatives)
                    for (const Successor& s : a.successors) next[v].push_back(&s);
            }
        // Strongly connected components (Tarjan).
        std::vector<int> index(n, -1), low(n, 0), comp(n, -1), stack;
        std::vector<char> onStack(n, 0);
        struct Frame {
            int v;
            std::size_t k;
        };
        std::vector<Frame> calls;
        int counter = 0, comps = 0;
        auto enter = [&](int v) {
            index[std::size_t(v)] = low[std::size_t(v)] = counter++;
            stack.push_back(v);
            onStack[std::size_t(v)] = 1;
            calls.push_back({v, 0});
        };
        for (std::size_t root = 0; root < n; ++root) {
            if (index[root] >= 0) continue;
            enter(int(root));
            while (!calls.empty()) {
                Frame& f = calls.back();
                const std::size_t v = std::size_t(f.v);
                if (f.k < next[v].size()) {
                    const int w = id.at(next[v][f.k++]->handle);
                    if (index[std::size_t(w)] < 0) enter(w);  // f may dangle now
                    else if (onStack[std::size_t(w)]) low[v] = std::min(low[v], index[std::size_t(w)]);
                    continue;
                }
                calls.pop_back();
                if (!calls.empty()) low[std::size_t(calls.back().v)] = std::min(low[std::size_t(calls.back().v)], low[v]);
                if (low[v] == index[v]) {
                    int w;
                    do {
                        w = stack.back();
                        stack.pop_back();
                        onStack[std::size_t(w)] = 0;
                        comp[std::size_t(w)] = comps;
                    } while (w != int(v));
                    ++comps;
                }
            }
        }
        for (std::size_t v = 0; v < n; ++v)
            for (const RuleDef* d : stochasticDefs[v])
                for (const Application& a : d->alternatives)
                    for (const Successor& s : a.successors)
                        if (comp[std::size_t(id.at(s.handle))] == comp[v]) recursive_.insert(d);
        for (std::size_t v = 0; v < n; ++v)
            for (const RuleDef* d : u.handles[u.order[v]]) {
                if (recursive_.count(d)) continue;
                for (const Application& a : d->alternatives)
                    for (const Successor& s : a.successors) inlineNext[v].push_back(&s);
            }
        // Inline calls must not cycle: depth first over the edges that stay inline. On the way
        // back (successors first) each handle's inline height is known: the longest chain of
        // inline calls below it. The shapevo language nests inline calls at most 32 deep (a CRL
        // level may take two: a helper rule and the handle), so where a handle would stand on
        // more than kInlineLevels levels, its tallest successors become genes of their own
        // (called through a child slot), and the chain starts again below them.
        constexpr int kInlineLevels = 12;
        std::vector<int> height(n, 0);
        auto settle = [&](std::size_t v) {
            auto tallest = [&] {
                int h = 0;
                for (const Successor* s : inlineNext[v]) {
                    const std::size_t w = std::size_t(id.at(s->handle));
                    if (!geneRoots_.count(u.prefix + s->handle)) h = std::max(h, height[w]);
                }
                return h + 1;
            };
            height[v] = tallest();
            if (height[v] <= kInlineLevels) return;
            for (const Successor* s : inlineNext[v])
                if (height[std::size_t(id.at(s->handle))] >= kInlineLevels / 2) geneRoots_.insert(u.prefix + s->handle);
            height[v] = tallest();
        };
        std::vector<char> mark(n, 0);  // 0 new, 1 on the path, 2 done
        for (std::size_t root = 0; root < n; ++root) {
            if (mark[root]) continue;
            mark[root] = 1;
            calls.push_back({int(root), 0});
            while (!calls.empty()) {
                Frame& f = calls.back();
                const std::size_t v = std::size_t(f.v);
                if (f.k == inlineNext[v].size()) {
                    mark[v] = 2;
                    settle(v);
                    calls.pop_back();
                    continue;
                }
                const Successor& s = *inlineNext[v][f.k++];
                const int w = id.at(s.handle);
                if (mark[std::size_t(w)] == 1) {
                    auto from = std::find_if(calls.begin(), calls.end(), [&](const Frame& e) { return e.v == w; });
                    std::string text;
                    const std::size_t length = std::size_t(calls.end() - from);
                    for (std::size_t k = 0; k < length; ++k) {
                        if (length > 12 && k == 5) {
                            text += "... (" + std::to_string(length - 10) + " more) -> ";
                            k = length - 5;
                        }
                        text += shortened(u.order[std::size_t(from[std::ptrdiff_t(k)].v)]) + " -> ";
                    }
                    failAt(s.where, "recursion never ends: " + text + shortened(s.handle) +
                                        " and no rule on the way is stochastic (a recursive rule must be, castlemaker-crl.txt ch. 4-5)");
                }
                if (mark[std::size_t(w)] == 0) {
                    mark[std::size_t(w)] = 1;
                    calls.push_back({w, 0});
                }
            }
        }
    }

    // --- emission ----------------------------------------------------------------------------
    void begin(const std::string& name, const Location& where) {
        pending_.emplace_back();
        cur_ = &pending_.back();
        cur_->push_back({where, "rule " + name + " {"});
        where_ = where;
    }
    void end() {
        cur_->push_back({cur_->front().where, "}"});
        rulesText_.insert(rulesText_.end(), cur_->begin(), cur_->end());
        pending_.pop_back();
        cur_ = pending_.empty() ? nullptr : &pending_.back();
    }

    void emitUnit(Unit& u) {
        unit_ = &u;
        for (const std::string& h : u.order)
            for (const RuleDef* d : u.handles[h]) {
                for (const Application& a : d->alternatives) check(u, a, false);
                if (stochastic(*d)) checkStochastic(*d);
            }
        for (const RuleDef* d : u.lots) check(u, d->alternatives[0], true);
        analyse(u);
        for (const std::string& h : u.order) {
            const auto& defs = u.handles[h];
            Location where = defs.empty() ? Location{} : defs.front()->where;
            if (defs.empty())
                for (const RuleDef* l : u.lots)
                    if (l->predecessor == h) where = l->where;
            begin(u.prefix + h, where);
            for (std::size_t i = 0; i < defs.size(); ++i) {
                const RuleDef& d = *defs[i];
                const bool last = i + 1 == defs.size();
                where_ = d.where;
                if (!last) line("[");
                if (!stochastic(d)) {
                    emitApplication(u, d.alternatives[0], false);
                } else if (recursive_.count(&d)) {
                    std::string slot = "child";
                    for (std::size_t k = 0; k < d.alternatives.size(); ++k) {
                        const Application& a = d.alternatives[k];
                        if (a.probability <= 0) continue;
                        const std::string name = u.prefix + h + "__s" + std::to_string(i + 1) + "a" + std::to_string(k + 1);
                        slot += std::string(slot == "child" ? " " : " | ") + "[" + number(a.probability) + "] " + name;
                        begin(name, a.where);
                        emitApplication(u, a, false);
                        end();
                    }
                    where_ = d.where;
                    line(slot + " optional");
                } else {
                    const std::string pick = declareParam("uniform(0, 1)");
                    double cumulative = 0;
                    for (std::size_t k = 0; k < d.alternatives.size(); ++k) {
                        const Application& a = d.alternatives[k];
                        cumulative += a.probability;
                        where_ = a.where;
                        if (k + 1 < d.alternatives.size()) line("case (" + pick + " < " + number(cumulative) + ") {");
                        else line("else {");
                        emitApplication(u, a, false);
                        where_ = a.where;
                        line("}");
                    }
                }
                where_ = d.where;
                if (!last) line("]");
            }
            end();
        }
    }

    Value argument(Unit& u, const Arg& a, ArgType type, const std::string& function) {
        Value v;
        v.where = a.where;
        auto bound = [&](const Arg& b) {
            if (b.kind == ArgKind::Name) {
                auto it = u.attrValue.find(b.text);
                if (it == u.attrValue.end()) failAt(b.where, "unknown attr '" + shortened(b.text) + "' (attrs are defined with attr name = value;)");
                return std::pair{u.prefix + b.text, it->second};
            }
            return std::pair{number(b.number), b.number};
        };
        if (type == ArgType::String) {
            if (a.kind != ArgKind::String)
                failAt(a.where, function + " expects a \"string\" here (a name or a file in quotes), found " +
                                    (a.kind == ArgKind::Number ? "number " + shown(a.number) : a.kind == ArgKind::Rand ? std::string("rand(...)") : "'" + shortened(a.text) + "' (not in quotes)"));
            v.text = a.text;
            v.constant = true;
            return v;
        }
        switch (a.kind) {
        case ArgKind::String: failAt(a.where, function + " expects a number here, found the string \"" + shortened(a.text) + "\"");
        case ArgKind::Number:
        case ArgKind::Name: {
            const auto [expr, value] = bound(a);
            v.expr = expr;
            v.value = value;
            v.constant = true;
            if (type != ArgType::Real && value != std::floor(value))
                failAt(a.where, function + " expects a whole number here, found " + shown(value));
            if (type == ArgType::Bool && value != 0 && value != 1) failAt(a.where, function + " expects 0 or 1 here, found " + shown(value));
            return v;
        }
        case ArgKind::Rand: {
            const auto [lo, loValue] = bound(a.bounds[0]);
            const auto [hi, hiValue] = bound(a.bounds[1]);
            if (loValue > hiValue) failAt(a.where, "rand(a, b) needs a <= b, found rand(" + shown(loValue) + ", " + shown(hiValue) + ")");
            if (type != ArgType::Real && std::floor(hiValue) < std::ceil(loValue))
                failAt(a.where, "rand(" + shown(loValue) + ", " + shown(hiValue) + ") holds no whole number, but " + function + " needs one here");
            if (type != ArgType::Real && (std::fabs(loValue) > 16777216 || std::fabs(hiValue) > 16777216))
                failAt(a.where, "a whole-number rand lies within +-16777216");
            v.expr = declareParam(std::string(type == ArgType::Real ? "uniform(" : "int(") + lo + ", " + hi + ")");
            return v;
        }
        }
        return v;
    }

    void emitApplication(Unit& u, const Application& app, bool inLot) {
        const Function* f = findFunction(app.function);
        where_ = app.where;
        Call c{*this, app, {}, {}, inLot};
        for (std::size_t k = 0; k < app.args.size(); ++k)
            c.args.push_back(argument(u, app.args[k], f->args[std::min(k, f->args.size() - 1)], app.function));
        for (const Successor& s : app.successors) {
            const std::string name = u.prefix + s.handle;
            if (!geneRoots_.count(name)) {
                c.successors.push_back(name);
                continue;
            }
            c.successors.push_back(name + "__gene");  // a rule whose one child slot derives `name`
            if (geneWrappers_.insert(name).second) {
                const Location where = where_;
                begin(name + "__gene", s.where);
                line("child " + name);
                end();
                where_ = where;
            }
        }
        where_ = app.where;
        f->emit(c);
    }

    /// An inserted rule file's lots, their bounding rectangle fitted to the frame's base.
    void modelRule(Unit& u, const Location& from) {
        if (u.lots.empty()) failAt(from, "the inserted rule file has no lot");
        double x1 = INFINITY, y1 = INFINITY, x2 = -INFINITY, y2 = -INFINITY;
        struct Box { double x1, y1, x2, y2; };
        std::vector<Box> boxes;
        for (const RuleDef* d : u.lots) {
            const Application& a = d->alternatives[0];
            std::vector<double> v;
            for (const Arg& arg : a.args) {
                if (arg.kind == ArgKind::Rand) failAt(arg.where, "an inserted rule file's lots need constant corners (rand() is not allowed here)");
                v.push_back(argument(u, arg, ArgType::Real, a.function).value);
            }
            Box b = a.function == "rect" ? Box{std::min(v[0], v[2]), std::min(v[1], v[3]), std::max(v[0], v[2]), std::max(v[1], v[3])}
                                         : Box{v[0] - v[2] / 2, v[1] - v[2] / 2, v[0] + v[2] / 2, v[1] + v[2] / 2};
            boxes.push_back(b);
            x1 = std::min(x1, b.x1), y1 = std::min(y1, b.y1), x2 = std::max(x2, b.x2), y2 = std::max(y2, b.y2);
        }
        const double w = std::max(x2 - x1, 1e-9), d = std::max(y2 - y1, 1e-9);
        begin(u.prefix + "model", from);
        for (std::size_t k = 0; k < boxes.size(); ++k) {
            const Box& b = boxes[k];
            where_ = u.lots[k]->where;
            line("[ translate (scope.size.x * " + number((b.x1 + b.x2) / 2 / w - (x1 + x2) / 2 / w) + ", 0, scope.size.z * " +
                 number(-((b.y1 + b.y2) / 2 / d - (y1 + y2) / 2 / d)) + ") size (scope.size.x * " + number((b.x2 - b.x1) / w) +
                 ", scope.size.y, scope.size.z * " + number((b.y2 - b.y1) / d) + ") " + u.prefix + u.lots[k]->predecessor + " ]");
        }
        end();
    }

    fs::path mainDir_;
    std::map<std::string, double> overrides_;
    Translation& out_;
    std::deque<Unit> units_;
    Unit* unit_ = nullptr;
    std::vector<std::string> stack_, inserting_, insertingNames_;  ///< inserting_: canonical; its names relative to the main folder
    std::set<const RuleDef*> recursive_;
    std::set<std::string> geneRoots_, geneWrappers_;  ///< handles called through a child slot (deep chains)
    std::deque<std::vector<Line>> pending_;
    std::vector<Line>* cur_ = nullptr;
    std::vector<Line> rulesText_, attrLines_;
    Location where_;
    int params_ = 0;
    std::map<std::string, std::string> models_, helpers_;
    friend struct Call;
};

void Call::line(const std::string& s) { t.line(s); }
void Call::fail(const Location& where, const std::string& what) const { failAt(where, what); }

std::string declareParam(Translator& t, const std::string& prior) { return t.declareParam(prior); }
std::string fileFor(Translator& t, const Location& at, const std::string& file, const char* what) { return t.fileFor(at, file, what); }
double objectHeight(Translator& t, const Location& at, const std::string& file) { return t.objectHeight(at, file); }
std::string insertedModel(Translator& t, const Location& at, const std::string& file, bool textured, bool local) {
    return t.insertedModel(at, file, textured, local);
}
Looks looks(const Translator& t) { return t.looks(); }
std::string helperRule(Translator& t, const std::string& key, const std::function<void()>& body) { return t.helper(key, body); }
std::string materialName(const Translator& t, const std::string& name) { return t.materialName(name); }

Translation translateCrl(const std::string& text, const std::string& path, const std::map<std::string, double>& attrs) {
    Translation out;
    Translator(path, attrs, out).run(text, path);
    return out;
}

}  // namespace shapevo::crl
