// Internal to the mesh reader: one parser per file format plus the small helpers they share
// (number parsing, vertex merging; little-endian decoding is base/little_endian.hpp). Users call readMesh() instead.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "base/input_error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_reader.hpp"

namespace shapevo::meshio {

/// Each parser gets the whole file as bytes; `path` is only used in error messages.
Mesh parseObj(std::string_view data, const std::string& path);
Mesh parsePly(std::string_view data, const std::string& path);
Mesh parseStl(std::string_view data, const std::string& path);

/// Reads `path` (of `fileBytes` bytes) with Assimp in a sandboxed child process (mesh/assimp_reader.cpp).
Mesh importWithAssimp(const std::string& path, std::uint64_t fileBytes, const MeshReadLimits& limits);
/// True if Assimp has an importer for `extension` (lower case, with the dot).
bool assimpReads(const std::string& extension);
/// Assimp's extensions but .obj, .ply and .stl (lower case, with the dot, sorted).
std::vector<std::string> assimpExtensionList();

/// Parses all of `token` as a decimal floating-point number; throws InputError at `where`.
double parseDouble(std::string_view token, const std::string& path, const std::string& where);
/// Parses all of `token` as a (possibly negative) integer; throws InputError at `where`.
long long parseInteger(std::string_view token, const std::string& path, const std::string& where);
/// Converts to float and rejects NaN/infinity (also values that overflow a float).
glm::vec3 finitePoint(double x, double y, double z, const std::string& path, const std::string& where);

/// Splits on blanks (space, tab, \r); keeps a view into the caller's buffer.
class Tokens {
public:
    explicit Tokens(std::string_view line) : rest_(line) {}
    /// Next token, or an empty view at the end.
    std::string_view next();
    bool done();

private:
    std::string_view rest_;
};

/// Merges exactly-equal positions (with -0 == +0) so soup formats (STL) come out indexed.
class VertexWelder {
public:
    explicit VertexWelder(Mesh& mesh) : mesh_(mesh) {}
    std::uint32_t add(const glm::vec3& p);

private:
    struct KeyHash {
        std::size_t operator()(const glm::vec3& p) const;
    };
    Mesh& mesh_;
    std::unordered_map<glm::vec3, std::uint32_t, KeyHash> index_;
};

}  // namespace shapevo::meshio
