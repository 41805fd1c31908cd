// Config reader: toml++ parse, --set overrides, then each stage reads its own section through a
// SectionReader (base/section_reader.hpp) implemented here over toml++; this file only gathers
// them (and reads [run] and [grammar], which are the run's own), checks across stages, and
// rejects what no stage asked for.
// A value that came from --set is blamed on --set, never on a line of the file; a value quoted
// in a message is cut to 80 characters.
#include "run/config_file.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include <toml++/toml.h>

#include "base/format_double.hpp"
#include "base/input_error.hpp"
#include "base/section_reader.hpp"
#include "checkpoint/checkpoint_section.hpp"
#include "genome/genome_section.hpp"
#include "island/migration_section.hpp"
#include "run/output_folder.hpp"
#include "run/run_limit.hpp"
#include "graph/graph_section.hpp"
#include "score/score_section.hpp"
#include "score/target_kinds.hpp"
#include "search/search_sections.hpp"

namespace shapevo {

namespace {

std::string place(const toml::node& n) {
    const auto& s = n.source();
    return std::to_string(s.begin.line) + ":" + std::to_string(s.begin.column);
}

class Reader {
public:
    Reader(const toml::table& root, std::string path) : root_(root), path_(std::move(path)) {}

    const std::string& path() const { return path_; }

    /// Values from --set were parsed on their own and carry no file: name the option instead.
    [[noreturn]] void fail(const toml::node& n, const std::string& what) const {
        if (!n.source().path) throw InputError("--set", "", what);
        throw InputError(path_, place(n), what);
    }

    /// The node of `sec`.`k` ("ga", "population"), or nullptr.
    const toml::node* find(const std::string& sec, const std::string& k) const {
        const toml::node* t = root_.get(sec);
        return t && t->is_table() ? t->as_table()->get(k) : nullptr;
    }

    /// A rule over several keys ("ga.elitism", "ga.population") is broken: blame --set if one of
    /// them came from it, else the place of the last of them in the file, else `section`.
    [[noreturn]] void failKeys(const std::vector<std::string>& keys, const std::string& section,
                               const std::string& what) const {
        const toml::node* last = nullptr;
        for (const std::string_view qualified : keys) {
            const auto dot = qualified.find('.');
            const toml::node* n = find(std::string(qualified.substr(0, dot)), std::string(qualified.substr(dot + 1)));
            if (!n) continue;
            if (!n->source().path) throw InputError("--set", "", what);
            const auto& a = n->source().begin;
            if (!last || a.line > last->source().begin.line ||
                (a.line == last->source().begin.line && a.column > last->source().begin.column))
                last = n;
        }
        if (last) throw InputError(path_, place(*last), what);
        throw InputError(path_, section, what);
    }

    /// Run `check`, a stage's own check that throws InputError(path_, "section.key", what): give
    /// its error the key's line, or blame --set if the key came from there.
    template <class F>
    void located(F&& check) const {
        try {
            check();
        } catch (const InputError& e) {
            const std::string& where = e.where();
            const auto dot = where.find('.');
            const toml::node* n = dot == std::string::npos ? nullptr : find(where.substr(0, dot), where.substr(dot + 1));
            if (!n) throw;
            if (!n->source().path) throw InputError("--set", where, e.message());
            throw InputError(path_, place(*n), where + ": " + e.message());
        }
    }

    const toml::table* section(const std::string& name) {
        known_[name];
        const toml::node* n = root_.get(name);
        if (!n) return nullptr;
        if (!n->is_table()) fail(*n, "[" + name + "] must be a table");
        return n->as_table();
    }
    const toml::node* key(const toml::table* t, const std::string& sec, const std::string& k) {
        known_[sec].insert(k);
        return t ? t->get(k) : nullptr;
    }
    template <class T>
    void number(const toml::table* t, const std::string& sec, const std::string& k, T& out, double lo, double hi) {
        const toml::node* n = key(t, sec, k);
        if (!n) return;
        double v;
        if (auto i = n->value_exact<std::int64_t>()) v = double(*i);
        else if (auto d = n->value_exact<double>()) v = *d;
        else fail(*n, sec + "." + k + " must be a number" + got(*n));
        if constexpr (std::is_integral_v<T>) {
            if (v != std::floor(v)) fail(*n, sec + "." + k + " must be a whole number");
        }
        if (!(v >= lo && v <= hi))
            fail(*n, sec + "." + k + " = " + toml_value(*n) + " is out of range [" + fmt(lo) + ", " + fmt(hi) + "]");
        out = T(v);
    }
    /// A whole number in [0, 2^63 - 1] (TOML's largest integer), read exactly (not through a double).
    void wholeNumber64(const toml::table* t, const std::string& sec, const std::string& k, std::uint64_t& out) {
        const toml::node* n = key(t, sec, k);
        if (!n) return;
        const std::string range = " is out of range [0, 9223372036854775807]";
        if (auto i = n->value_exact<std::int64_t>()) {
            if (*i < 0) fail(*n, sec + "." + k + " = " + std::to_string(*i) + range);
            out = std::uint64_t(*i);
        } else if (auto d = n->value_exact<double>()) {
            if (*d != std::floor(*d)) fail(*n, sec + "." + k + " must be a whole number");
            if (!(*d >= 0 && *d <= 9.007199254740992e15))  // exact as a double; write larger ones as integers
                fail(*n, sec + "." + k + " = " + toml_value(*n) + range + " (write large seeds as integers, not floats)");
            out = std::uint64_t(*d);
        } else {
            fail(*n, sec + "." + k + " must be a whole number" + got(*n));
        }
    }
    void string(const toml::table* t, const std::string& sec, const std::string& k, std::string& out) {
        const toml::node* n = key(t, sec, k);
        if (!n) return;
        if (!n->is_string()) fail(*n, sec + "." + k + " must be a string");
        out = *n->value<std::string>();
    }
    void boolean(const toml::table* t, const std::string& sec, const std::string& k, bool& out) {
        const toml::node* n = key(t, sec, k);
        if (!n) return;
        if (!n->is_boolean()) fail(*n, sec + "." + k + " must be true or false" + got(*n));
        out = *n->value<bool>();
    }
    std::vector<std::string> strings(const toml::table* t, const std::string& sec, const std::string& k) {
        std::vector<std::string> out;
        const toml::node* n = key(t, sec, k);
        if (!n) return out;
        if (n->is_string()) return {*n->value<std::string>()};
        if (!n->is_array()) fail(*n, sec + "." + k + " must be a string or an array of strings");
        for (const auto& e : *n->as_array()) {
            if (!e.is_string()) fail(e, sec + "." + k + " must hold strings only");
            out.push_back(*e.value<std::string>());
        }
        return out;
    }
    /// An array of exactly out.size() numbers; returns whether the key is present.
    bool numbers(const toml::table* t, const std::string& sec, const std::string& k, std::span<double> out) {
        const toml::node* n = key(t, sec, k);
        if (!n) return false;
        const std::string what = sec + "." + k + " must be an array of " + std::to_string(out.size()) + " numbers";
        const toml::array* a = n->as_array();
        if (!a || a->size() != out.size()) fail(*n, what);
        for (std::size_t i = 0; i < out.size(); ++i) {
            const auto& e = (*a)[i];
            if (auto v = e.value<double>()) out[i] = *v;
            else fail(e, what);
        }
        return true;
    }
    /// A table of finite numbers into `out`; returns whether the key is present.
    bool numberTable(const toml::table* t, const std::string& sec, const std::string& k, std::map<std::string, double>& out) {
        const toml::node* n = key(t, sec, k);
        if (!n) return false;
        if (!n->is_table()) fail(*n, sec + "." + k + " must be a table of numbers ([" + sec + "." + k + "] NAME = 1.5)");
        for (const auto& [name, value] : *n->as_table()) {
            double v = 0;
            if (auto i = value.value_exact<std::int64_t>()) v = double(*i);
            else if (auto d = value.value_exact<double>()) v = *d;
            else fail(value, sec + "." + k + "." + std::string(name.str()) + " must be a number");
            if (!std::isfinite(v)) fail(value, sec + "." + k + "." + std::string(name.str()) + " must be a finite number");
            out[std::string(name.str())] = v;
        }
        return true;
    }
    /// Every key present must have been asked for.
    void rejectUnknown() const {
        for (const auto& [k, v] : root_) {
            const std::string name(k.str());
            auto it = known_.find(name);
            if (it == known_.end())
                fail(v, "unknown section [" + shortened(name) + "] (expected one of: " + list(known_) + ")");
            for (const auto& entry : *v.as_table()) {
                const toml::key& kk = entry.first;
                if (!it->second.count(std::string(kk.str()))) {
                    const std::string what = "unknown key '" + shortened(kk.str()) + "' in [" + name +
                                             "] (expected one of: " + join(it->second) + ")";
                    if (!kk.source().path) throw InputError("--set", "", what);
                    throw InputError(path_, std::to_string(kk.source().begin.line) + ":" +
                                                std::to_string(kk.source().begin.column), what);
                }
            }
        }
    }

private:
    static std::string fmt(double v) {
        std::ostringstream s;
        s << v;
        return s.str();
    }
    static std::string toml_value(const toml::node& n) {
        std::ostringstream s;
        n.visit([&](auto&& v) { s << v; });
        return shortened(s.str());
    }
    /// ", got \"text\"" for a string value (cut to 80 characters), "" otherwise.
    static std::string got(const toml::node& n) {
        if (const auto* str = n.as_string()) return ", got \"" + shortened(str->get()) + "\"";
        return "";
    }
    static std::string join(const std::set<std::string>& s) {
        std::string r;
        for (const auto& x : s) r += (r.empty() ? "" : ", ") + x;
        return r;
    }
    static std::string list(const std::map<std::string, std::set<std::string>>& m) {
        std::string r;
        for (const auto& [k, v] : m) r += (r.empty() ? "" : ", ") + k;
        return r;
    }
    const toml::table& root_;
    std::string path_;
    std::map<std::string, std::set<std::string>> known_;
};

void applyOverride(toml::table& root, const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError("--set", assignment, "expected key=value, e.g. ga.population=50");
    const std::string key = assignment.substr(0, eq), value = assignment.substr(eq + 1);
    const auto dot = key.find('.');
    if (dot == std::string::npos) throw InputError("--set", assignment, "expected section.key=value, e.g. ga.population=50");
    const std::string section = key.substr(0, dot), name = key.substr(dot + 1);
    toml::table parsed;
    try {
        parsed = toml::parse("v = " + value);
    } catch (const toml::parse_error&) {
        parsed = toml::table{{"v", value}};  // a bare word: take it as a string
    }
    if (!root.contains(section)) root.insert(section, toml::table{});
    toml::table* t = root[section].as_table();
    if (!t) throw InputError("--set", assignment, "[" + shortened(section) + "] is not a table in the config");
    // section.table.key (grammar.attr.height=12): walk into (or make) the nested tables.
    std::string leaf = name;
    for (auto dot2 = leaf.find('.'); dot2 != std::string::npos; dot2 = leaf.find('.')) {
        const std::string inner = leaf.substr(0, dot2);
        if (!t->contains(inner)) t->insert(inner, toml::table{});
        t = (*t)[inner].as_table();
        if (!t) throw InputError("--set", assignment, shortened(section + "." + inner) + " is not a table in the config");
        leaf = leaf.substr(dot2 + 1);
    }
    t->insert_or_assign(leaf, std::move(*parsed.get("v")));
}

/// A key's default as TOML writes it, for the reference.
std::string tomlText(double v) { return std::isnan(v) ? "" : formatDouble(v); }  // NaN: no default
std::string tomlText(const std::string& v) { return v.empty() ? "" : "\"" + v + "\""; }
std::string tomlText(std::span<const double> v) {
    for (double x : v)
        if (std::isnan(x)) return "";
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + formatDouble(v[i]);
    return out + "]";
}
std::string rangeText(double lo, double hi) {
    std::ostringstream s;
    s << "[" << lo << ", " << hi << "]";
    return s.str();
}

/// A SectionReader over one [section] of the config: the stages read their own keys through it.
/// With `keys`, it also records each key it is asked for (the first time).
class TomlSection final : public SectionReader {
public:
    TomlSection(Reader& rd, std::string section, std::filesystem::path folder, std::vector<ConfigKeyRecord>* keys)
        : rd_(rd), section_(std::move(section)), t_(rd.section(section_)), folder_(std::move(folder)), keys_(keys) {}
    void number(std::string_view key, double& v, double lo, double hi, std::string_view meaning) override {
        record(key, "number", tomlText(v), rangeText(lo, hi), meaning);
        rd_.number(t_, section_, std::string(key), v, lo, hi);
    }
    void count(std::string_view key, std::uint32_t& v, double lo, double hi, std::string_view meaning) override {
        record(key, "whole number", tomlText(v), rangeText(lo, hi), meaning);
        rd_.number(t_, section_, std::string(key), v, lo, hi);
    }
    void wholeNumber64(std::string_view key, std::uint64_t& v, std::string_view meaning) override {
        record(key, "whole number", std::to_string(v), "[0, 9223372036854775807]", meaning);
        rd_.wholeNumber64(t_, section_, std::string(key), v);
    }
    void flag(std::string_view key, bool& v, std::string_view meaning) override {
        record(key, "true or false", v ? "true" : "false", "", meaning);
        rd_.boolean(t_, section_, std::string(key), v);
    }
    void string(std::string_view key, std::string& v, std::string_view meaning) override {
        record(key, "string", tomlText(v), "", meaning);
        rd_.string(t_, section_, std::string(key), v);
    }
    std::vector<std::string> strings(std::string_view key, std::string_view meaning) override {
        record(key, "string or array of strings", "[]", "", meaning);
        return rd_.strings(t_, section_, std::string(key));
    }
    bool numbers(std::string_view key, std::span<double> v, std::string_view meaning) override {
        record(key, "array of " + std::to_string(v.size()) + " numbers", tomlText(v), "", meaning);
        return rd_.numbers(t_, section_, std::string(key), v);
    }
    bool numberTable(std::string_view key, std::map<std::string, double>& v, std::string_view meaning) override {
        record(key, "table of numbers", "{}", "", meaning);
        return rd_.numberTable(t_, section_, std::string(key), v);
    }
    bool has(std::string_view key) override { return rd_.key(t_, section_, std::string(key)) != nullptr; }
    bool present() const override { return t_ != nullptr; }
    const std::string& file() const override { return rd_.path(); }
    std::string resolvePath(const std::string& p) const override {
        return std::filesystem::path(p).is_absolute() ? p : (folder_ / p).lexically_normal().string();
    }
    [[noreturn]] void fail(std::string_view key, const std::string& what) const override {
        const toml::node* n = t_ ? t_->get(key) : nullptr;
        if (!n) throw InputError(rd_.path(), "[" + section_ + "]", what);
        rd_.fail(*n, what);
    }
    [[noreturn]] void failKeys(const std::vector<std::string>& keys, const std::string& where,
                               const std::string& what) const override {
        rd_.failKeys(keys, where, what);
    }
    [[noreturn]] void failSection(const std::string& what) const override {
        if (t_ && !t_->source().path) throw InputError("--set", "", what);
        throw InputError(rd_.path(), "[" + section_ + "]", what);
    }
    void located(const std::function<void()>& check) const override { rd_.located(check); }

private:
    void record(std::string_view key, std::string type, std::string defaultValue, std::string range, std::string_view meaning) {
        if (!keys_) return;
        for (const ConfigKeyRecord& k : *keys_)
            if (k.section == section_ && k.key == key) return;
        keys_->push_back({section_, std::string(key), std::move(type), std::move(defaultValue), std::move(range), std::string(meaning)});
    }

    Reader& rd_;
    std::string section_;
    const toml::table* t_;
    std::filesystem::path folder_;
    std::vector<ConfigKeyRecord>* keys_;
};

/// The config's sections, each opened (and made known) when a stage first asks for it.
class TomlConfig final : public ConfigReader {
public:
    TomlConfig(Reader& rd, std::filesystem::path folder, std::vector<ConfigKeyRecord>* keys)
        : rd_(rd), folder_(std::move(folder)), keys_(keys) {}
    SectionReader& section(std::string_view name) override {
        for (const auto& s : sections_)
            if (s.first == name) return *s.second;
        sections_.emplace_back(std::string(name), std::make_unique<TomlSection>(rd_, std::string(name), folder_, keys_));
        return *sections_.back().second;
    }

private:
    Reader& rd_;
    std::filesystem::path folder_;
    std::vector<ConfigKeyRecord>* keys_;
    std::vector<std::pair<std::string, std::unique_ptr<TomlSection>>> sections_;
};

/// [run]: name, seed, threads, out, wall_time, target_fitness.
void readRunSection(SectionReader& r, RunSettings& run) {
    // The rule a name follows, as the reference states it and as an error quotes it.
    const std::string plainName = "a plain name: 1-" + std::to_string(kMaxRunNameLength) +
                                  " bytes, no '/', '\\' or control character, not starting with '.' or '-'";
    r.string("name", run.name, "names the default output folder runs/<name>: " + plainName);
    if (const std::string problem = runNameProblem(run.name); !problem.empty())
        r.fail("name", "run.name = \"" + shortened(run.name) + "\" " + problem +
                           "; it names the output folder runs/<name>, so it must be " + plainName);
    r.wholeNumber64("seed", run.seed, "the run's seed (--seed overrides); one seed gives one run on any machine and thread count");
    std::uint32_t threads = std::uint32_t(run.threads);
    r.count("threads", threads, 0, 4096,
            "evaluation threads per rank, 0 = all cores (--threads overrides); more than the machine gives are cut to what it "
            "gives; results do not depend on it");
    run.threads = int(threads);
    r.string("out", run.out, "the output folder (--out overrides); default runs/<name>");
    r.number("wall_time", run.wallTime, 0, 1e9, "stop (with a checkpoint) after this many seconds of the whole run, summed over resumes; 0 = no "
             "limit. Without ga.generations the run lasts this long; with it, whichever comes first");
    double targetFitness = std::nan("");
    r.number("target_fitness", targetFitness, -1e300, 1e300, "stop when any island's best fitness reaches it; none when absent");
    if (!std::isnan(targetFitness)) run.targetFitness = targetFitness;
}

/// [grammar]: file (resolved against the config's folder) and [grammar.attr] NAME = number.
void readGrammarSection(SectionReader& r, RunSettings& run) {
    r.string("file", run.grammarPath,
             "the grammar file (.grammar, a CastleMaker rule file .rule or a procedural content graph .pcg), relative to the config's folder; required");
    if (run.grammarPath.empty()) r.failKeys({"grammar.file"}, "", "missing [grammar] file = \"...\"");
    run.grammarPath = r.resolvePath(run.grammarPath);
    r.numberTable("attr", run.grammarAttrs,
                  "values for the grammar's attrs ([grammar.attr] NAME = 1.5), replacing those the grammar file gives");
}

/// Checks across stages, after each has read its own keys: the initial lengths fit the genome's
/// limit and each other.
void checkInitialGenes(const Reader& rd, const RunSettings& r) {
    const auto n = [](std::uint32_t v) { return std::to_string(v); };
    const PopulationSettings& g = r.population;
    if (g.initialGenesMin > r.limits.maxGenes)
        rd.failKeys({"ga.initial_genes_min", "genome.max_genes"}, "[ga]",
                    "ga.initial_genes_min = " + n(g.initialGenesMin) + " exceeds genome.max_genes = " + n(r.limits.maxGenes) +
                        "; no chromosome is longer than max_genes");
    // The default initial_genes_max (40) may exceed a small max_genes (growth stops there, as
    // before); one that is given must fit.
    if (rd.find("ga", "initial_genes_max") && g.initialGenesMax > r.limits.maxGenes)
        rd.failKeys({"ga.initial_genes_max", "genome.max_genes"}, "[ga]",
                    "ga.initial_genes_max = " + n(g.initialGenesMax) + " exceeds genome.max_genes = " + n(r.limits.maxGenes) +
                        "; no chromosome is longer than max_genes");
    if (g.initialGenesMin > g.initialGenesMax)
        rd.failKeys({"ga.initial_genes_min", "ga.initial_genes_max"}, "[ga]",
                    "initial_genes_min must not exceed initial_genes_max (ga.initial_genes_min = " + n(g.initialGenesMin) +
                        ", ga.initial_genes_max = " + n(g.initialGenesMax) + ")");
}

/// Migration sends the best `count` to replace the receiver's worst, never its elites.
void checkMigrationCount(const Reader& rd, const RunSettings& r) {
    const auto n = [](std::uint32_t v) { return std::to_string(v); };
    if (r.migration.count > r.population.population - r.ga.elitism && r.migration.interval > 0)
        rd.failKeys({"migration.count", "migration.interval", "ga.population", "ga.elitism"}, "[migration]",
                    "count must not exceed population - elitism (migration.count = " + n(r.migration.count) +
                        ", ga.population - ga.elitism = " + n(r.population.population - r.ga.elitism) + ")");
}

/// A relative file path a target kind reads from [target] (target.image) given with --set was
/// typed in the shell: take it from the current directory (not the config's), and record it
/// absolute so that a resume finds the same file.
void absoluteShellPaths(toml::table& root) {
    toml::table* t = root["target"].as_table();
    if (!t) return;
    for (const TargetKind* kind : targetKinds())
        for (std::string_view key : kind->shellRelativeFiles)
            if (const toml::node* n = t->get(key); n && !n->source().path)
                if (const auto v = n->value_exact<std::string>(); v && !v->empty() && !std::filesystem::path(*v).is_absolute())
                    t->insert_or_assign(key, std::filesystem::absolute(*v).lexically_normal().string());
}

}  // namespace

RunSettings parseConfig(const std::string& text, const std::string& path, const std::vector<std::string>& overrides,
                        std::vector<ConfigKeyRecord>* keys) {
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        const auto& s = e.source();
        throw InputError(path, std::to_string(s.begin.line) + ":" + std::to_string(s.begin.column),
                         std::string(e.description()));
    }
    for (const auto& o : overrides) applyOverride(root, o);
    absoluteShellPaths(root);

    RunSettings r;
    r.configPath = path;
    {
        std::ostringstream s;
        s << root;
        r.configText = overrides.empty() ? text : s.str();
    }
    Reader rd(root, path);
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    TomlConfig config(rd, folder, keys);
    // Each stage reads its own section; the order is the order errors are found in.
    readRunSection(config.section("run"), r);
    readGrammarSection(config.section("grammar"), r);
    r.target = readTargetSettings(config);
    readScoreSection(config.section("score"), r.fitness, r.incremental);
    graph::readGraphSection(config.section("graph"), r.graphLimits);
    readGenomeSection(config.section("genome"), r.limits);
    readGaSection(config.section("ga"), r.population, r.ga);
    r.generationsGiven = rd.find("ga", "generations") != nullptr;
    settleRunLimit(r);
    checkInitialGenes(rd, r);
    readSearchSection(config.section("search"), r.search);
    readMigrationSection(config.section("migration"), r.migration);
    checkMigrationCount(rd, r);
    readCheckpointSection(config.section("checkpoint"), r.checkpoint);
    rd.rejectUnknown();
    return r;
}

RunSettings loadConfig(const std::string& path, const std::vector<std::string>& overrides) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(path, "", "is a folder, not a config file (name the .toml file, e.g. configs/spaceship.toml)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "", "cannot open config file");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw InputError(path, "", "cannot read config file");
    return parseConfig(ss.str(), path, overrides);
}

}  // namespace shapevo
