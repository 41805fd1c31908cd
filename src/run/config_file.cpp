// Config reader: toml++ parse, --set overrides, then a strict walk over known sections and keys.
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

#include "base/section_reader.hpp"
#include "base/input_error.hpp"
#include "run/output_folder.hpp"
#include "search/search_methods.hpp"

namespace shapevo {

namespace {

std::string place(const toml::node& n) {
    const auto& s = n.source();
    return std::to_string(s.begin.line) + ":" + std::to_string(s.begin.column);
}

class Reader {
public:
    Reader(const toml::table& root, std::string path) : root_(root), path_(std::move(path)) {}

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
    [[noreturn]] void failKeys(std::initializer_list<std::string_view> keys, const std::string& section,
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
    bool vec3(const toml::table* t, const std::string& sec, const std::string& k, glm::dvec3& out) {
        const toml::node* n = key(t, sec, k);
        if (!n) return false;
        const toml::array* a = n->as_array();
        if (!a || a->size() != 3) fail(*n, sec + "." + k + " must be an array of 3 numbers");
        for (int i = 0; i < 3; ++i) {
            const auto& e = (*a)[std::size_t(i)];
            if (auto v = e.value<double>()) out[i] = *v;
            else fail(e, sec + "." + k + " must be an array of 3 numbers");
        }
        return true;
    }
    bool vec2(const toml::table* t, const std::string& sec, const std::string& k, glm::dvec2& out) {
        const toml::node* n = key(t, sec, k);
        if (!n) return false;
        const toml::array* a = n->as_array();
        if (!a || a->size() != 2) fail(*n, sec + "." + k + " must be an array of 2 numbers");
        for (int i = 0; i < 2; ++i) {
            const auto& e = (*a)[std::size_t(i)];
            if (auto v = e.value<double>()) out[i] = *v;
            else fail(e, sec + "." + k + " must be an array of 2 numbers");
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

/// A SectionReader over one [section] of the config, for stages that read their own keys.
class TomlSection final : public SectionReader {
public:
    TomlSection(Reader& rd, const toml::table* t, std::string section) : rd_(rd), t_(t), section_(std::move(section)) {}
    void number(std::string_view key, double& v, double lo, double hi) override { rd_.number(t_, section_, std::string(key), v, lo, hi); }
    void count(std::string_view key, std::uint32_t& v, double lo, double hi) override {
        rd_.number(t_, section_, std::string(key), v, lo, hi);
    }
    void flag(std::string_view key, bool& v) override {
        if (const toml::node* n = rd_.key(t_, section_, std::string(key))) {
            if (!n->is_boolean()) rd_.fail(*n, section_ + "." + std::string(key) + " must be true or false");
            v = *n->value<bool>();
        }
    }

private:
    Reader& rd_;
    const toml::table* t_;
    std::string section_;
};

/// [search]: the method (a name in search/search_methods.cpp's table) and every method's own
/// keys, each read by the method's entry (so a key of another method is known, not an error).
void readSearch(Reader& rd, RunSettings& r) {
    const toml::table* t = rd.section("search");
    SearchSettings& s = r.search;
    rd.string(t, "search", "method", s.method);
    if (!findSearchMethod(s.method))
        rd.fail(*t->get("method"), "search.method must be " + searchMethodNames() + ", got \"" + shortened(s.method) + "\"");
    rd.boolean(t, "search", "diagnostics", s.diagnostics);
    TomlSection section(rd, t, "search");
    for (const SearchMethodEntry& e : searchMethods()) e.readSettings(section, s);
}

/// [camera]: projection = "perspective" | "orthographic" | "shadow" and its settings; checked by
/// Camera::compile when the scene is loaded.
void readCamera(Reader& rd, const toml::table* t, CameraSpec& c, const std::string& path) {
    const std::string sec = "camera";
    std::string projection = "perspective";
    rd.string(t, sec, "projection", projection);
    if (projection == "perspective") c.projection = Projection::Perspective;
    else if (projection == "orthographic") c.projection = Projection::Orthographic;
    else if (projection == "shadow") c.projection = Projection::Shadow;
    else rd.fail(*t->get("projection"), "camera.projection must be \"perspective\", \"orthographic\" or \"shadow\", got \"" + shortened(projection) + "\"");
    rd.number(t, sec, "width", c.width, 1, 16384);
    rd.number(t, sec, "height", c.height, 1, 16384);
    rd.vec3(t, sec, "eye", c.eye);
    rd.vec3(t, sec, "look_at", c.lookAt);
    rd.vec3(t, sec, "up", c.up);
    rd.number(t, sec, "fov_degrees", c.fovDegrees, -1e9, 1e9);
    rd.number(t, sec, "view_height", c.viewHeight, -1e12, 1e12);
    rd.number(t, sec, "near", c.near, -1e12, 1e12);
    rd.vec3(t, sec, "light", c.light);
    rd.number(t, sec, "ground_y", c.groundY, -1e12, 1e12);
    rd.vec2(t, sec, "ground_min", c.groundMin);
    rd.vec2(t, sec, "ground_max", c.groundMax);
    rd.located([&] { Camera::compile(c, path, sec); });  // located errors now, not when the run starts
}

}  // namespace

RunSettings parseConfig(const std::string& text, const std::string& path, const std::vector<std::string>& overrides) {
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        const auto& s = e.source();
        throw InputError(path, std::to_string(s.begin.line) + ":" + std::to_string(s.begin.column),
                         std::string(e.description()));
    }
    for (const auto& o : overrides) applyOverride(root, o);
    // A relative target.image given with --set was typed in the shell: take it from the current
    // directory (not the config's), and record it absolute so that a resume finds the same file.
    if (toml::table* t = root["target"].as_table())
        if (const toml::node* n = t->get("image"); n && !n->source().path)
            if (const auto v = n->value_exact<std::string>(); v && !v->empty() && !std::filesystem::path(*v).is_absolute())
                t->insert_or_assign("image", std::filesystem::absolute(*v).lexically_normal().string());

    RunSettings r;
    r.configPath = path;
    {
        std::ostringstream s;
        s << root;
        r.configText = overrides.empty() ? text : s.str();
    }
    const std::filesystem::path base = std::filesystem::path(path).parent_path();
    auto resolve = [&](const std::string& p) {
        return std::filesystem::path(p).is_absolute() ? p : (base / p).lexically_normal().string();
    };
    Reader rd(root, path);

    const toml::table* run = rd.section("run");
    rd.string(run, "run", "name", r.name);
    if (const std::string problem = runNameProblem(r.name); !problem.empty())
        rd.fail(*run->get("name"), "run.name = \"" + shortened(r.name) + "\" " + problem +
                                       "; it names the output folder runs/<name>, so it must be a plain name: 1-" +
                                       std::to_string(kMaxRunNameLength) +
                                       " bytes, no '/', '\\' or control character, not starting with '.' or '-'");
    rd.wholeNumber64(run, "run", "seed", r.seed);
    rd.number(run, "run", "threads", r.threads, 0, 4096);
    rd.string(run, "run", "out", r.out);
    rd.number(run, "run", "wall_time", r.wallTime, 0, 1e9);
    if (rd.key(run, "run", "target_fitness")) {
        double t = 0;
        rd.number(run, "run", "target_fitness", t, -1e300, 1e300);
        r.targetFitness = t;
    }

    const toml::table* grammar = rd.section("grammar");
    rd.string(grammar, "grammar", "file", r.grammarPath);
    if (r.grammarPath.empty()) rd.failKeys({"grammar.file"}, "", "missing [grammar] file = \"...\"");
    r.grammarPath = resolve(r.grammarPath);
    if (const toml::node* attrs = rd.key(grammar, "grammar", "attr")) {
        if (!attrs->is_table()) rd.fail(*attrs, "grammar.attr must be a table of numbers ([grammar.attr] NAME = 1.5)");
        for (const auto& [name, value] : *attrs->as_table()) {
            double v = 0;
            if (auto i = value.value_exact<std::int64_t>()) v = double(*i);
            else if (auto d = value.value_exact<double>()) v = *d;
            else rd.fail(value, "grammar.attr." + std::string(name.str()) + " must be a number");
            if (!std::isfinite(v)) rd.fail(value, "grammar.attr." + std::string(name.str()) + " must be a finite number");
            r.grammarAttrs[std::string(name.str())] = v;
        }
    }

    const toml::table* target = rd.section("target");
    for (const auto& f : rd.strings(target, "target", "fill")) r.targets.push_back({resolve(f), false});
    for (const auto& f : rd.strings(target, "target", "avoid")) r.targets.push_back({resolve(f), true});
    GridOverride grid;
    const bool hasMin = rd.vec3(target, "target", "grid_min", grid.min);
    const bool hasMax = rd.vec3(target, "target", "grid_max", grid.max);
    rd.number(target, "target", "voxel_size", grid.voxelSize, 1e-6, 1e6);
    std::string image;
    rd.string(target, "target", "image", image);
    ImageSceneSettings pixels;
    rd.number(target, "target", "hit_min", pixels.rule.hitMin, 0, 255);
    rd.number(target, "target", "hit_max", pixels.rule.hitMax, 0, 255);
    rd.number(target, "target", "avoid_min", pixels.rule.avoidMin, 0, 255);
    rd.number(target, "target", "avoid_max", pixels.rule.avoidMax, 0, 255);
    rd.number(target, "target", "alpha_threshold", pixels.rule.alphaThreshold, 0, 256);
    // target.cover: a preset for the four ranges, so it is either it or them; alpha_threshold
    // goes with both.
    std::string cover;
    rd.string(target, "target", "cover", cover);
    if (rd.key(target, "target", "cover")) {
        const TargetCover presets[] = {TargetCover::Dark, TargetCover::Light, TargetCover::Opaque};
        const TargetCover* preset = nullptr;
        for (const TargetCover& c : presets)
            if (cover == targetCoverName(c)) preset = &c;
        if (!preset)
            rd.fail(*target->get("cover"), "target.cover must be \"dark\", \"light\" or \"opaque\", got \"" + shortened(cover) + "\"");
        for (const char* k : {"hit_min", "hit_max", "avoid_min", "avoid_max"})
            if (rd.key(target, "target", k))
                rd.failKeys({"target.cover", "target.hit_min", "target.hit_max", "target.avoid_min", "target.avoid_max"}, "[target]",
                            "target.cover and target." + std::string(k) +
                                " both say which pixels to cover: give the preset (cover = \"dark\", \"light\" or "
                                "\"opaque\") or the luminance ranges (hit_min, hit_max, avoid_min, avoid_max), not both");
        pixels.rule = PixelRule::forCover(*preset, pixels.rule.alphaThreshold);
    }
    std::string fit = targetFitName(pixels.fit);
    rd.string(target, "target", "fit", fit);
    if (rd.key(target, "target", "fit")) {
        bool known = false;
        for (TargetFit f : {TargetFit::Contain, TargetFit::Cover, TargetFit::Stretch, TargetFit::Exact})
            if (fit == targetFitName(f)) pixels.fit = f, known = true;
        if (!known)
            rd.fail(*target->get("fit"),
                    "target.fit must be \"contain\", \"cover\", \"stretch\" or \"exact\", got \"" + shortened(fit) + "\"");
    }
    rd.number(target, "target", "scale", pixels.scale, 0.01, 1.0);
    if (rd.key(target, "target", "scale") && pixels.scale < 1.0 && pixels.fit != TargetFit::Contain &&
        pixels.fit != TargetFit::Stretch)
        rd.failKeys({"target.scale", "target.fit"}, "[target]",
                    "target.scale makes the picture take part of the frame, which only target.fit = \"contain\" or "
                    "\"stretch\" do (\"" + std::string(targetFitName(pixels.fit)) + "\" takes the whole frame)");
    const toml::table* camera = rd.section("camera");
    if (!image.empty()) {
        if (!r.targets.empty() || hasMin || hasMax || rd.key(target, "target", "voxel_size"))
            rd.failKeys({"target.image", "target.fill", "target.avoid", "target.grid_min", "target.grid_max", "target.voxel_size"},
                        "[target]", "an image target cannot be combined with fill/avoid volumes or a grid");
        pixels.png = resolve(image);
        rd.located([&] { pixels.rule.check(path, "target"); });
        readCamera(rd, camera, pixels.camera, path);
        r.image = pixels;
    } else {
        if (camera) {
            if (!camera->source().path) throw InputError("--set", "", "a camera is only used with an image target ([target] image = \"FILE.png\")");
            throw InputError(path, "[camera]", "a camera is only used with an image target ([target] image = \"FILE.png\")");
        }
        if (r.targets.empty() || r.targets.front().avoid)
            rd.failKeys({"target.fill", "target.avoid"}, "",
                        "missing [target] fill = \"FILE.vdb\" (at least one fill target) or image = \"FILE.png\"");
        if (hasMin != hasMax || (hasMin && grid.voxelSize <= 0) || (!hasMin && rd.key(target, "target", "voxel_size")))
            rd.failKeys({"target.grid_min", "target.grid_max", "target.voxel_size"}, "[target]",
                        "grid_min, grid_max and voxel_size must be given together");
        if (hasMin) r.grid = grid;
    }

    const toml::table* score = rd.section("score");
    std::string form = "smootherstep";
    rd.string(score, "score", "form", form);
    if (form == "smootherstep") r.fitness.form = VolumeFitnessSettings::Form::Smootherstep;
    else if (form == "weighted") r.fitness.form = VolumeFitnessSettings::Form::WeightedSum;
    else rd.fail(*score->get("form"), "score.form must be \"smootherstep\" or \"weighted\", got \"" + shortened(form) + "\"");
    auto& f = r.fitness;
    constexpr double big = 1e12;
    rd.number(score, "score", "alpha", f.alpha, -big, big);
    rd.number(score, "score", "beta", f.beta, -big, big);
    rd.number(score, "score", "gamma", f.gamma, -big, big);
    rd.number(score, "score", "length_optimal", f.lengthOptimal, 0, big);
    rd.number(score, "score", "length_max", f.lengthMax, 0, big);
    rd.number(score, "score", "fill_weight", f.fillWeight, -big, big);
    rd.number(score, "score", "empty_weight", f.emptyWeight, -big, big);
    rd.number(score, "score", "avoid_weight", f.avoidWeight, -big, big);
    rd.number(score, "score", "overlap_weight", f.overlapWeight, -big, big);
    rd.number(score, "score", "outside_weight", f.outsideWeight, -big, big);
    rd.boolean(score, "score", "incremental", r.incremental.enabled);
    rd.number(score, "score", "cache_mb", r.incremental.cacheMb, 1, 1 << 20);
    rd.boolean(score, "score", "check_incremental", r.incremental.check);
    if (f.lengthMax <= f.lengthOptimal)
        rd.failKeys({"score.length_optimal", "score.length_max"}, "[score]", "length_max must be greater than length_optimal");

    const toml::table* genome = rd.section("genome");
    rd.number(genome, "genome", "max_genes", r.limits.maxGenes, 1, 1e7);
    rd.number(genome, "genome", "max_primitives", r.limits.maxPrimitives, 1, 1 << 26);

    const toml::table* ga = rd.section("ga");
    auto& g = r.ga;
    rd.number(ga, "ga", "population", g.population, 2, 1e7);
    rd.number(ga, "ga", "generations", g.generations, 1, 1e9);
    rd.number(ga, "ga", "elitism", g.elitism, 0, 1e7);
    rd.number(ga, "ga", "tournament", g.tournament, 1, 1e7);
    rd.number(ga, "ga", "mutation", g.mutation, 0, 1);
    rd.number(ga, "ga", "grow", g.growWeight, 0, big);
    rd.number(ga, "ga", "cut", g.cutWeight, 0, big);
    rd.number(ga, "ga", "alter", g.alterWeight, 0, big);
    rd.number(ga, "ga", "crossover_retries", g.crossoverRetries, 1, 1000);
    rd.number(ga, "ga", "initial_genes_min", g.initialGenesMin, 1, 1e7);
    rd.number(ga, "ga", "initial_genes_max", g.initialGenesMax, 1, 1e7);
    const auto n = [](std::uint32_t v) { return std::to_string(v); };
    if (g.elitism >= g.population)
        rd.failKeys({"ga.elitism", "ga.population"}, "[ga]",
                    "elitism must be smaller than population (ga.elitism = " + n(g.elitism) + ", ga.population = " + n(g.population) + ")");
    if (g.tournament > g.population)
        rd.failKeys({"ga.tournament", "ga.population"}, "[ga]",
                    "tournament must not exceed population (ga.tournament = " + n(g.tournament) + ", ga.population = " + n(g.population) + ")");
    if (g.growWeight + g.cutWeight + g.alterWeight <= 0)
        rd.failKeys({"ga.grow", "ga.cut", "ga.alter"}, "[ga]", "grow, cut and alter weights must not all be 0");
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
    readSearch(rd, r);
    const toml::table* migration = rd.section("migration");
    rd.number(migration, "migration", "interval", r.migration.interval, 0, 1e9);
    rd.number(migration, "migration", "count", r.migration.count, 0, 1e7);
    rd.number(migration, "migration", "meeting_interval", r.migration.meetingInterval, 0, 1e9);
    std::string mode = "sync";
    rd.string(migration, "migration", "mode", mode);
    if (mode != "sync" && mode != "async")
        rd.fail(*migration->get("mode"), "migration.mode must be \"sync\" or \"async\", got \"" + shortened(mode) + "\"");
    r.migration.async = mode == "async";
    if (r.migration.count > g.population - g.elitism && r.migration.interval > 0)
        rd.failKeys({"migration.count", "migration.interval", "ga.population", "ga.elitism"}, "[migration]",
                    "count must not exceed population - elitism (migration.count = " + n(r.migration.count) +
                        ", ga.population - ga.elitism = " + n(g.population - g.elitism) + ")");

    const toml::table* checkpoint = rd.section("checkpoint");
    rd.number(checkpoint, "checkpoint", "interval", r.checkpoint.interval, 0, 1e9);
    rd.number(checkpoint, "checkpoint", "seconds", r.checkpoint.seconds, 0, 1e9);
    rd.number(checkpoint, "checkpoint", "keep", r.checkpoint.keep, 1, 1e6);
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
