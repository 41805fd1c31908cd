// libFuzzer target for one mesh format: arbitrary bytes -> meshio::parseObj / parsePly /
// parseStl (the in-memory parsers readMesh calls after reading the file), chosen at compile time
// by SHAPEVO_FUZZ_MESH_FORMAT (0 OBJ, 1 PLY, 2 STL); tests/fuzz/CMakeLists.txt builds it three
// times as fuzz_obj_reader, fuzz_ply_reader and fuzz_stl_reader.
//
// An InputError is the expected way to reject input; any other exception, a sanitizer report or
// a broken invariant of an accepted mesh is a crash. An accepted mesh has only finite vertices
// and in-range indices (STL: no two equal vertices, as they are welded), requireClosed either
// passes or throws InputError, and a closed mesh goes the user's way too: written to a file,
// loadMeshShape (readMesh + requireClosed + normalization) must give the same triangles and
// vertices inside [-1, 1]^3.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <tuple>

#include "base/input_error.hpp"
#include "mesh/mesh_formats.hpp"
#include "mesh/mesh_reader.hpp"
#include "mesh/mesh_shape_file.hpp"
#include "scratch_folder.hpp"

#ifndef SHAPEVO_FUZZ_MESH_FORMAT
#error "define SHAPEVO_FUZZ_MESH_FORMAT (0 OBJ, 1 PLY, 2 STL)"
#endif

namespace {

using namespace shapevo;

[[noreturn]] void broken(const char* what) {
    std::fprintf(stderr, "fuzz_mesh_reader: invariant broken: %s\n", what);
    std::abort();
}
#define CHECK(cond) \
    do {            \
        if (!(cond)) broken(#cond); \
    } while (0)

constexpr const char* kExtension[] = {".obj", ".ply", ".stl"};
std::string folder;  // this process's temporary folder

Mesh parse(std::string_view data, const std::string& path) {
    switch (SHAPEVO_FUZZ_MESH_FORMAT) {
        case 0: return meshio::parseObj(data, path);
        case 1: return meshio::parsePly(data, path);
        default: return meshio::parseStl(data, path);
    }
}

void checkAccepted(const Mesh& m) {
    for (const std::string& w : m.warnings) CHECK(w.rfind("fuzz.mesh", 0) == 0);  // each names the file
    for (const glm::vec3& v : m.vertices) CHECK(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
    for (const auto& t : m.triangles)
        for (std::uint32_t i : t) CHECK(i < m.vertices.size());
    if (SHAPEVO_FUZZ_MESH_FORMAT == 2) {  // welded: every position once (-0 == +0)
        std::set<std::tuple<float, float, float>> seen;
        for (const glm::vec3& v : m.vertices) CHECK(seen.insert({v.x + 0.0f, v.y + 0.0f, v.z + 0.0f}).second);
    }
}

void checkShape(std::string_view data, const Mesh& m) {
    const std::string path = folder + "/mesh" + kExtension[SHAPEVO_FUZZ_MESH_FORMAT];
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f || std::fwrite(data.data(), 1, data.size(), f) != data.size() || std::fclose(f) != 0) {
        std::perror(path.c_str());
        std::abort();
    }
    MeshShape s;
    try {
        s = loadMeshShape(path);
    } catch (const InputError& e) {
        // Only a mesh whose triangles all lack an area may fail here (readMesh: "no valid face";
        // loadMeshShape: "no extent", all vertices at one position).
        CHECK(std::strstr(e.what(), "no valid face") != nullptr || std::strstr(e.what(), "no extent") != nullptr);
        return;
    }
    CHECK(s.triangles == m.triangles && s.vertices.size() == m.vertices.size());
    for (const glm::vec3& v : s.vertices)
        for (int a = 0; a < 3; ++a) CHECK(v[a] >= -1.0f && v[a] <= 1.0f);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    folder = shapevo::fuzz::scratchFolder("fuzz_mesh_reader");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    Mesh m;
    try {
        m = parse(bytes, "fuzz.mesh");
    } catch (const InputError& e) {
        CHECK(std::strncmp(e.what(), "fuzz.mesh", 9) == 0);
        return 0;
    }
    checkAccepted(m);
    if (m.triangles.empty()) return 0;  // readMesh refuses it
    try {
        requireClosed(m, "fuzz.mesh");
    } catch (const InputError&) {
        return 0;
    }
    checkShape(bytes, m);
    return 0;
}
