// PLY parser (ascii and binary_little_endian): reads x/y/z of the `vertex` element and the
// `vertex_indices` (or `vertex_index`) list of the `face` element; skips every other element
// and property. Polygons are fan-triangulated. A header line that starts with no PLY keyword
// (Blender 2.4x writes "Created by Blender 2.49 - www.blender.org, source file: ..." without
// `comment`) is skipped with a warning in Mesh::warnings (the first kMaxHeaderWarnings, then a count).
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "base/little_endian.hpp"
#include "mesh/mesh_formats.hpp"

namespace shapevo::meshio {

namespace {

constexpr std::size_t kMaxHeaderWarnings = 5;

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct Property {
    std::string name;
    Type type = Type::Float32;  ///< item type for lists
    bool isList = false;
    Type countType = Type::UInt8;
};

struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> properties;
};

bool parseType(std::string_view s, Type& t) {
    static const std::pair<std::string_view, Type> names[] = {
        {"char", Type::Int8},     {"int8", Type::Int8},       {"uchar", Type::UInt8},    {"uint8", Type::UInt8},
        {"short", Type::Int16},   {"int16", Type::Int16},     {"ushort", Type::UInt16},  {"uint16", Type::UInt16},
        {"int", Type::Int32},     {"int32", Type::Int32},     {"uint", Type::UInt32},    {"uint32", Type::UInt32},
        {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64}};
    for (const auto& [name, type] : names)
        if (s == name) return t = type, true;
    return false;
}

std::size_t byteSize(Type t) {
    switch (t) {
        case Type::Int8: case Type::UInt8: return 1;
        case Type::Int16: case Type::UInt16: return 2;
        case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
        case Type::Float64: return 8;
    }
    return 1;
}

bool isIntegral(Type t) { return t != Type::Float32 && t != Type::Float64; }

/// The body of the file after end_header, in either encoding; all values come out as doubles
/// (every PLY scalar type converts to double exactly).
class Body {
public:
    virtual ~Body() = default;
    virtual double read(Type t, const std::string& element, std::size_t index) = 0;
    virtual std::string where(const std::string& element, std::size_t index) const = 0;
};

class AsciiBody : public Body {
public:
    AsciiBody(std::string_view data, std::size_t firstLine, const std::string& path)
        : rest_(data), line_(firstLine), path_(path) {}

    double read(Type t, const std::string& element, std::size_t index) override {
        std::string_view token = nextToken();
        if (token.empty())
            throw InputError(path_, where(element, index), "unexpected end of file in " + element + " " +
                                                                std::to_string(index));
        const std::string at = where(element, index);
        return isIntegral(t) ? double(parseInteger(token, path_, at)) : parseDouble(token, path_, at);
    }
    std::string where(const std::string&, std::size_t) const override { return std::to_string(line_); }

private:
    std::string_view nextToken() {
        std::size_t i = 0;
        for (; i < rest_.size(); ++i) {
            const char c = rest_[i];
            if (c == '\n') ++line_;
            else if (c != ' ' && c != '\t' && c != '\r') break;
        }
        std::size_t j = i;
        while (j < rest_.size() && rest_[j] != ' ' && rest_[j] != '\t' && rest_[j] != '\r' && rest_[j] != '\n') ++j;
        const std::string_view token = rest_.substr(i, j - i);
        rest_.remove_prefix(j);
        return token;
    }
    std::string_view rest_;
    std::size_t line_;
    const std::string& path_;
};

class BinaryLittleEndianBody : public Body {
public:
    BinaryLittleEndianBody(std::string_view data, std::size_t offset, const std::string& path)
        : data_(data), pos_(offset), path_(path) {}

    double read(Type t, const std::string& element, std::size_t index) override {
        const std::size_t n = byteSize(t);
        if (data_.size() - pos_ < n)
            throw InputError(path_, where(element, index), "unexpected end of file");
        const auto* p = reinterpret_cast<const unsigned char*>(data_.data() + pos_);
        pos_ += n;
        switch (t) {
            case Type::Int8: return double(std::int8_t(p[0]));
            case Type::UInt8: return double(p[0]);
            case Type::Int16: return double(std::int16_t(std::uint16_t(p[0] | p[1] << 8)));
            case Type::UInt16: return double(std::uint16_t(p[0] | p[1] << 8));
            case Type::Int32: return double(std::int32_t(le::load<std::uint32_t>(p)));
            case Type::UInt32: return double(le::load<std::uint32_t>(p));
            case Type::Float32: return double(le::load<float>(p));
            case Type::Float64: return le::load<double>(p);
        }
        return 0.0;
    }
    std::string where(const std::string& element, std::size_t index) const override {
        return element + " " + std::to_string(index) + " (byte " + std::to_string(pos_) + ")";
    }

private:
    std::string_view data_;
    std::size_t pos_;
    const std::string& path_;
};

std::string numberText(double v) {
    return v == std::floor(v) && std::fabs(v) < 1e15 ? std::to_string(static_cast<long long>(v)) : std::to_string(v);
}

std::string_view nextLine(std::string_view& data) {
    const std::size_t eol = data.find('\n');
    std::string_view line = data.substr(0, eol);
    data.remove_prefix(eol == std::string_view::npos ? data.size() : eol + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
}

}  // namespace

Mesh parsePly(std::string_view data, const std::string& path) {
    // --- header ---
    std::string_view rest = data;
    std::size_t lineNo = 1;
    if (nextLine(rest) != "ply") throw InputError(path, "1", "not a PLY file (first line must be 'ply')");
    bool binary = false, sawFormat = false, sawEnd = false;
    std::vector<Element> elements;
    std::vector<std::string> warnings;
    std::size_t skipped = 0;
    while (!rest.empty() && !sawEnd) {
        const std::string where = std::to_string(++lineNo);
        const std::string_view line = nextLine(rest);
        Tokens tokens(line);
        const std::string_view keyword = tokens.next();
        if (keyword == "format") {
            const std::string_view format = tokens.next();
            if (format == "ascii") binary = false;
            else if (format == "binary_little_endian") binary = true;
            else throw InputError(path, where, "unsupported PLY format '" + std::string(format) +
                                                   "' (expected ascii or binary_little_endian)");
            sawFormat = true;
        } else if (keyword == "element") {
            Element e;
            e.name = std::string(tokens.next());
            const long long count = parseInteger(tokens.next(), path, where);
            if (e.name.empty() || count < 0) throw InputError(path, where, "malformed element line");
            e.count = std::size_t(count);
            elements.push_back(std::move(e));
        } else if (keyword == "property") {
            if (elements.empty()) throw InputError(path, where, "property before any element");
            Property p;
            std::string_view type = tokens.next();
            if (type == "list") {
                p.isList = true;
                if (!parseType(tokens.next(), p.countType)) throw InputError(path, where, "unknown list count type");
                type = tokens.next();
            }
            if (!parseType(type, p.type)) throw InputError(path, where, "unknown property type '" + std::string(type) + "'");
            p.name = std::string(tokens.next());
            elements.back().properties.push_back(std::move(p));
        } else if (keyword == "end_header") {
            sawEnd = true;
        } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
            if (++skipped <= kMaxHeaderWarnings)
                warnings.push_back(path + ": line " + where + ": skipped the header line '" + shortened(line, 100) +
                                   "' (not a PLY keyword; a comment needs 'comment' before it)");
        }
    }
    if (skipped > kMaxHeaderWarnings)
        warnings.push_back(path + ": skipped " + std::to_string(skipped - kMaxHeaderWarnings) +
                           " more header lines that start with no PLY keyword");
    if (!sawFormat) throw InputError(path, "", "PLY header has no format line");
    if (!sawEnd) throw InputError(path, "", "PLY header has no end_header line");

    // --- which properties matter ---
    std::size_t vertexCount = 0;
    bool sawVertex = false;
    for (const Element& e : elements) {
        if (e.name != "vertex") continue;
        sawVertex = true;
        vertexCount = e.count;
        for (const char* axis : {"x", "y", "z"}) {
            bool found = false;
            for (const Property& p : e.properties) found |= (p.name == axis && !p.isList);
            if (!found) throw InputError(path, "", std::string("PLY vertex element has no '") + axis + "' property");
        }
    }
    if (!sawVertex) throw InputError(path, "", "PLY file has no vertex element");

    // --- body ---
    const std::size_t bodyStart = data.size() - rest.size();
    std::unique_ptr<Body> body;
    if (binary) body = std::make_unique<BinaryLittleEndianBody>(data, bodyStart, path);
    else body = std::make_unique<AsciiBody>(rest, lineNo + 1, path);

    Mesh mesh;
    mesh.warnings = std::move(warnings);
    mesh.vertices.reserve(std::min(vertexCount, data.size()));
    std::vector<std::uint32_t> polygon;
    for (const Element& e : elements) {
        const bool isVertex = e.name == "vertex", isFace = e.name == "face";
        if (e.properties.empty()) continue;  // nothing stored per item
        for (std::size_t i = 0; i < e.count; ++i) {
            double xyz[3] = {0, 0, 0};
            for (const Property& p : e.properties) {
                if (!p.isList) {
                    const double v = body->read(p.type, e.name, i);
                    if (isVertex && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z') xyz[p.name[0] - 'x'] = v;
                    continue;
                }
                const double count = body->read(p.countType, e.name, i);
                const bool indices = isFace && (p.name == "vertex_indices" || p.name == "vertex_index");
                // A float count type may hold NaN, a fraction or 1e30: converting those to size_t is UB.
                if (!(count >= 0 && count <= 4294967295.0 && count == std::floor(count)))
                    throw InputError(path, body->where(e.name, i),
                                     "list length " + numberText(count) + " is not a whole number from 0 to 4294967295");
                if (indices && count < 3)
                    throw InputError(path, body->where(e.name, i),
                                     "face has " + std::to_string(long(count)) + " vertices, needs at least 3");
                polygon.clear();
                for (std::size_t k = 0; k < std::size_t(count); ++k) {
                    const double v = body->read(p.type, e.name, i);
                    if (!indices) continue;
                    if (v < 0 || v >= double(vertexCount) || v != std::floor(v))
                        throw InputError(path, body->where(e.name, i),
                                         "face index " + numberText(v) + " out of range (" +
                                             std::to_string(vertexCount) + " vertices)");
                    polygon.push_back(std::uint32_t(v));
                }
                for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
                    mesh.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
            }
            if (isVertex) mesh.vertices.push_back(finitePoint(xyz[0], xyz[1], xyz[2], path, body->where(e.name, i)));
        }
    }
    return mesh;
}

}  // namespace shapevo::meshio
