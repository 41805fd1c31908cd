// libFuzzer target for the mesh formats read through Assimp: the first byte picks an extension
// (kExtensions[byte % count]: OFF, glTF, GLB, FBX, 3MF, DAE, 3DS, ...), the other bytes are
// written to a file with that extension in this process's scratch folder, and readMesh reads it
// (Assimp in its sandboxed child process, then the same checks as every reader).
//
// An InputError naming the file is the expected way to reject input; any other exception, a
// sanitizer report or a broken invariant is a crash: an accepted mesh has at least one triangle
// with an area, finite vertices, indices in range and warnings that name the file, and no import
// process is left behind (no child that appeared during readMesh is still running or unreaped).
// Children from before the call do not count: the sanitizer runtime starts an llvm-symbolizer
// child the first time libFuzzer prints NEW_FUNC and keeps it, so "no child at all" is false.
// Assimp itself is not instrumented: what it does wrong shows up as a crash, hang or
// out-of-memory of the child, which readMesh must turn into an InputError.
// With SHAPEVO_FUZZ_ASSIMP_FAILURES=<folder>, inputs on which Assimp's process crashed, hung or
// ran out of memory are copied there (to see what the sandbox absorbed).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "base/input_error.hpp"
#include "mesh/mesh_reader.hpp"
#include "../child_processes.hpp"
#include "scratch_folder.hpp"

namespace {

using namespace shapevo;

[[noreturn]] void broken(const char* what) {
    std::fprintf(stderr, "fuzz_mesh_import: invariant broken: %s\n", what);
    std::abort();
}
#define CHECK(cond) \
    do {            \
        if (!(cond)) broken(#cond); \
    } while (0)

// Keep in step with make_seeds.py (the seeds' first bytes) and mesh_import.dict.
constexpr const char* kExtensions[] = {".off", ".gltf", ".glb", ".fbx", ".3mf", ".dae", ".3ds", ".x",
                                       ".ac",  ".ase",  ".b3d", ".ms3d", ".nff", ".smd", ".amf", ".blend"};
constexpr std::size_t kCount = sizeof kExtensions / sizeof kExtensions[0];
std::string folder;

void writeInput(const std::string& path, std::string_view bytes) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f || std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size() || std::fclose(f) != 0) {
        std::perror(path.c_str());
        std::abort();
    }
}

void keepAssimpFailure(std::string_view bytes, const char* ext, const char* message) {
    const char* dir = std::getenv("SHAPEVO_FUZZ_ASSIMP_FAILURES");
    if (!dir || !*dir) return;
    if (!std::strstr(message, "Assimp could not import it")) return;
    static unsigned n = 0;
    writeInput(std::string(dir) + "/failure" + std::to_string(++n) + ext, bytes);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    folder = shapevo::fuzz::scratchFolder("fuzz_mesh_import");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const char* ext = kExtensions[data[0] % kCount];
    const std::string path = folder + "/mesh" + ext;
    const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    writeInput(path, bytes);
    MeshReadLimits limits;
    // A hang is the sandbox's to stop (Assimp loops for ever on some SMD files): 2 s, well below
    // libFuzzer's -timeout (25 s in .ci/fuzz) and far above what these small inputs need, so
    // mutants of a hanging seed do not eat the run.
    limits.seconds = 2;
    const test::ChildProcessWatch children;
    try {
        const Mesh m = readMesh(path, limits);
        CHECK(!m.triangles.empty());
        for (const glm::vec3& v : m.vertices) CHECK(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
        for (const auto& t : m.triangles)
            for (std::uint32_t i : t) CHECK(i < m.vertices.size());
        bool someArea = false;
        for (const auto& t : m.triangles) {
            const glm::dvec3 a(m.vertices[t[0]]), b(m.vertices[t[1]]), c(m.vertices[t[2]]);
            someArea = someArea || glm::length(glm::cross(b - a, c - a)) > 0.0;
        }
        CHECK(someArea);
        for (const std::string& w : m.warnings) CHECK(w.rfind(path, 0) == 0);
    } catch (const InputError& e) {
        CHECK(std::strncmp(e.what(), path.c_str(), path.size()) == 0);
        CHECK(std::strchr(e.what(), '\n') == nullptr);
        keepAssimpFailure(bytes, ext, e.what());
    }
    CHECK(children.newChildren().empty());
    return 0;
}
