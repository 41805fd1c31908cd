// Value: the dynamic values of a 2D graph grammar's attributes and expressions (graph-grammar
// README, section 3): None, bool, int, float, str, tuple, a 2D vector and a reference to a graph
// element (vertex or edge) with its attribute map. Python's semantics where the original relies on
// them: truthiness, == across types (False == 0, a string never equals a number), repr of floats.
// Attribute names are interned once per grammar (AttrNames), so an element's map is a short vector
// of (key, value) pairs in insertion order — the order the SVG writer and `self_` updates follow.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace shapevo::graph {

/// An interned attribute name (index into AttrNames).
using AttrKey = std::uint32_t;

/// Attribute names of one grammar, each interned once when the file is read.
class AttrNames {
public:
    AttrKey intern(std::string_view name);
    /// The key of `name`, or kNone if no file element or expression uses it.
    AttrKey find(std::string_view name) const;
    const std::string& name(AttrKey k) const { return names_[k]; }
    std::size_t size() const { return names_.size(); }
    static constexpr AttrKey kNone = 0xffffffffu;

private:
    std::vector<std::string> names_;
};

struct AttrMap;

/// A 2D vector (model units, y up).
struct Vec2 {
    double x = 0, y = 0;
    friend bool operator==(const Vec2&, const Vec2&) = default;
};

/// A graph element seen by an expression: its attribute map and, for a vertex, its position.
/// Points into the host graph (or a snapshot, for `old`); valid during one evaluation only.
struct ElementRef {
    const AttrMap* attrs = nullptr;
    bool isVertex = true;
    Vec2 position;  // a vertex's x, y (an edge: unused)
};

struct Value;
using Tuple = std::shared_ptr<const std::vector<Value>>;

struct Value {
    using Data = std::variant<std::monostate, bool, std::int64_t, double, std::string, Tuple, Vec2, ElementRef>;
    Data data;

    Value() = default;
    Value(bool b) : data(b) {}
    Value(std::int64_t i) : data(i) {}
    Value(int i) : data(std::int64_t(i)) {}
    Value(double d) : data(d) {}
    Value(std::string s) : data(std::move(s)) {}
    Value(const char* s) : data(std::string(s)) {}
    Value(Tuple t) : data(std::move(t)) {}
    Value(Vec2 v) : data(v) {}
    Value(ElementRef e) : data(e) {}

    bool isNone() const { return data.index() == 0; }
    const bool* asBool() const { return std::get_if<bool>(&data); }
    const std::int64_t* asInt() const { return std::get_if<std::int64_t>(&data); }
    const double* asFloat() const { return std::get_if<double>(&data); }
    const std::string* asString() const { return std::get_if<std::string>(&data); }
    const Tuple* asTuple() const { return std::get_if<Tuple>(&data); }
    const Vec2* asVec() const { return std::get_if<Vec2>(&data); }
    const ElementRef* asElement() const { return std::get_if<ElementRef>(&data); }
};

/// Python's truth value: None, False, 0, 0.0, '' and () are false; everything else true.
bool truthy(const Value& v);
/// Python's == (False == 0 == 0.0; a string never equals a number; tuples element-wise;
/// elements by identity).
bool equal(const Value& a, const Value& b);
/// Python's str(): 'None', 'True', ints in decimal, floats as repr (shortest round trip, '1.0',
/// 'inf', '1e+16'), strings as they are, tuples as '(1, 2)', vectors as 'Vec(x, y)'.
std::string toText(const Value& v);
/// The type's name as Python says it, for messages: 'NoneType', 'bool', 'int', 'float', 'str',
/// 'tuple', 'Vec', 'element'.
const char* typeName(const Value& v);
/// A number as double (bool and int too); nullptr-like false when `v` is not a number.
bool numberOf(const Value& v, double& out);

/// One element's attributes, in insertion order (later sets of a key replace in place).
struct AttrMap {
    std::vector<std::pair<AttrKey, Value>> entries;
    const Value* find(AttrKey k) const {
        for (const auto& [key, value] : entries)
            if (key == k) return &value;
        return nullptr;
    }
    void set(AttrKey k, Value v) {
        for (auto& [key, value] : entries)
            if (key == k) {
                value = std::move(v);
                return;
            }
        entries.emplace_back(k, std::move(v));
    }
    void erase(AttrKey k) {
        for (std::size_t i = 0; i < entries.size(); ++i)
            if (entries[i].first == k) {
                entries.erase(entries.begin() + std::ptrdiff_t(i));
                return;
            }
    }
};

}  // namespace shapevo::graph
