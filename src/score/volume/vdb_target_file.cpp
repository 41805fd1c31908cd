// Volume target files: mesh -> level-set VDB (written atomically, never clobbering by accident),
// and VDB files -> the dense VolumeTarget the scorer reads.
#include "score/volume/vdb_target_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <sstream>

#include <openvdb/io/File.h>
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "base/atomic_write.hpp"
#include "base/hash.hpp"
#include "base/input_error.hpp"
#include "mesh/corner_box.hpp"
#include "score/volume/vdb_bake.hpp"
#include "score/volume/vdb_write.hpp"

namespace shapevo {

namespace fs = std::filesystem;

namespace {

void initOpenVdb() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

/// Meshes more than this many voxels across are almost surely a mistyped voxel size.
constexpr double kMaxVoxelsAcross = 20000.0;

std::string number(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

/// True when every corner of `mesh`'s triangles lies in one plane (within a millionth of the
/// mesh's size): such a mesh encloses no volume, however it is closed. The plane is that of the
/// largest triangle; a mesh of degenerate triangles only (no plane) counts as flat.
bool allInOnePlane(const Mesh& mesh) {
    glm::dvec3 normal(0.0), origin(0.0);
    double largest = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a(mesh.vertices[t[0]]), b(mesh.vertices[t[1]]), c(mesh.vertices[t[2]]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) > largest) largest = glm::length(n), normal = n / largest, origin = a;
    }
    if (!(largest > 0.0)) return true;
    const CornerBox box = cornerBox(mesh);
    const double tolerance = 1e-6 * glm::length(glm::dvec3(box.hi) - glm::dvec3(box.lo));
    for (const auto& t : mesh.triangles)
        for (std::uint32_t i : t)
            if (std::abs(glm::dot(glm::dvec3(mesh.vertices[i]) - origin, normal)) > tolerance) return false;
    return true;
}

}  // namespace

TargetVdbStats writeTargetVdb(const Mesh& mesh, double voxelSize, const std::string& sourcePath,
                              const std::string& outPath, bool overwrite) {
    initOpenVdb();
    if (!(voxelSize > 0.0) || !std::isfinite(voxelSize))
        throw InputError(sourcePath, "", "voxel size must be a positive number, got " + number(voxelSize));
    if (mesh.triangles.empty()) throw InputError(sourcePath, "", "mesh has no triangles");
    std::error_code ec;
    if (!overwrite && fs::exists(outPath, ec))
        throw InputError(outPath, "", "already exists; refusing to overwrite it");

    openvdb::Vec3d lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    std::vector<openvdb::Vec3s> points;
    points.reserve(mesh.vertices.size());
    for (const glm::vec3& v : mesh.vertices) {
        points.emplace_back(v.x, v.y, v.z);
        lo = openvdb::math::minComponent(lo, openvdb::Vec3d(v.x, v.y, v.z));
        hi = openvdb::math::maxComponent(hi, openvdb::Vec3d(v.x, v.y, v.z));
    }
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        for (std::uint32_t i : tri)
            if (i >= mesh.vertices.size())
                throw InputError(sourcePath, "triangle " + std::to_string(t),
                                 "vertex index " + std::to_string(i) + " out of range");
        triangles.emplace_back(tri[0], tri[1], tri[2]);
    }
    if (allInOnePlane(mesh))
        throw InputError(sourcePath, "", "the mesh encloses no volume: all its " + std::to_string(mesh.triangles.size()) +
                                             " triangles lie in one plane (a flat mesh has no inside)");
    const double across = (hi - lo).length() / voxelSize;
    if (across > kMaxVoxelsAcross)
        throw InputError(sourcePath, "", "voxel size " + number(voxelSize) + " is too small: the mesh would be " +
                                             number(std::ceil(across)) + " voxels across (limit " +
                                             number(kMaxVoxelsAcross) + ")");

    const openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(voxelSize);
    openvdb::FloatGrid::Ptr grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(
        *xform, points, triangles, float(openvdb::LEVEL_SET_HALF_WIDTH));
    if (!grid || grid->activeVoxelCount() == 0)
        throw InputError(sourcePath, "", "the level set is empty at voxel size " + number(voxelSize));
    // Every stored value (leaf voxels, and tiles: the interior's inactive negative tiles count as
    // many voxels as they cover); the unstored background is outside. A voxel centre on the
    // surface (value 0) counts as inside, but only one clearly inside (below a thousandth of a
    // voxel) shows that the mesh encloses a volume: a zero-thickness mesh passing through voxel
    // centres has values of 0 (or rounding's -epsilon) there and nothing below.
    TargetVdbStats stats;
    std::uint64_t clearlyInside = 0;
    const float clearly = float(-1e-3 * voxelSize);
    for (auto it = grid->cbeginValueAll(); it; ++it) {
        if (*it <= 0.0f) stats.insideVoxels += it.getVoxelCount();
        if (*it < clearly) clearlyInside += it.getVoxelCount();
    }
    stats.insideVolume = double(stats.insideVoxels) * voxelSize * voxelSize * voxelSize;
    if (clearlyInside == 0)
        throw InputError(sourcePath, "", "the inside of the mesh comes out empty at voxel size " + number(voxelSize) +
                                             ": no voxel centre is enclosed (an open surface, a surface of zero "
                                             "thickness, or a mesh thinner than a voxel; try a smaller --voxel-size)");
    grid->setName("target");
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    grid->insertMeta("voxel_size", openvdb::DoubleMetadata(voxelSize));
    grid->insertMeta("bounds_min", openvdb::Vec3DMetadata(lo));
    grid->insertMeta("bounds_max", openvdb::Vec3DMetadata(hi));
    grid->insertMeta("source", openvdb::StringMetadata(sourcePath));
    grid->insertMeta("shapevo_role", openvdb::StringMetadata("fill"));

    writeVdbGrid(grid, outPath, overwrite ? Replace::Always : Replace::Never);
    return stats;
}

namespace {

/// The file's bytes, read once: they are parsed and hashed from memory.
std::string readBytes(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(path, "", "cannot open VDB file: is a directory");
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path, "", "cannot open VDB file");
    std::string bytes;
    std::vector<char> block(1 << 16);
    while (file) {
        file.read(block.data(), std::streamsize(block.size()));
        bytes.append(block.data(), std::size_t(file.gcount()));
    }
    if (!file.eof()) throw InputError(path, "", "cannot read VDB file");
    return bytes;
}

/// Reads the float grid named "target" if there is one, else the first float level set, else
/// the first float grid; refuses it unless it is a non-empty level set (GRID_LEVEL_SET). The file
/// is read once; `fileHash` is hash64 of its bytes (what hashFile gives).
openvdb::FloatGrid::Ptr readLevelSet(const std::string& path, std::uint64_t& fileHash) {
    std::string bytes = readBytes(path);
    fileHash = hash64(bytes);
    std::istringstream in(std::move(bytes));
    openvdb::GridPtrVecPtr grids;
    try {
        // A read past the end throws at once. (openvdb::io::File reads on with garbage instead: a
        // file cut short "holds no grid", or a length read from nowhere allocates gigabytes.)
        in.exceptions(std::ios::failbit | std::ios::badbit | std::ios::eofbit);
        openvdb::io::Stream stream(in, /*delayLoad=*/false);
        grids = stream.getGrids();
    } catch (const std::ios_base::failure&) {
        throw InputError(path, "", "is truncated or unreadable: the file ends inside its VDB data");
    } catch (const std::exception& e) {
        // OpenVDB's messages about damaged files can quote megabytes of the damage: cut them.
        throw InputError(path, "", "is truncated or unreadable: not a readable VDB file (OpenVDB: " + shortened(e.what()) + ")");
    }
    if (!grids || grids->empty()) throw InputError(path, "", "holds no grids (expected a level set)");
    openvdb::FloatGrid::Ptr chosen;
    auto rank = [](const openvdb::FloatGrid& f) {
        return f.getName() == "target" ? 2 : f.getGridClass() == openvdb::GRID_LEVEL_SET ? 1 : 0;
    };
    for (const openvdb::GridBase::Ptr& g : *grids) {
        auto f = openvdb::gridPtrCast<openvdb::FloatGrid>(g);
        if (f && (!chosen || rank(*f) > rank(*chosen))) chosen = f;
    }
    if (!chosen) throw InputError(path, "", "holds no float grid (expected a level set)");
    const std::string grid = "grid '" + shortened(chosen->getName()) + "'";
    if (chosen->getGridClass() == openvdb::GRID_FOG_VOLUME)
        throw InputError(path, "", grid + " is a fog volume; expected a level set");
    if (chosen->activeVoxelCount() == 0) throw InputError(path, "", grid + " is empty");
    if (chosen->getGridClass() != openvdb::GRID_LEVEL_SET)
        throw InputError(path, "", grid + " is not a level set (its grid class is '" +
                                       openvdb::GridBase::gridClassToString(chosen->getGridClass()) +
                                       "'); a target must be a signed-distance level set (class level set), as "
                                       "`shapevo target` writes");
    return chosen;
}

GridSpec overrideGrid(const GridOverride& o) {
    const std::string what = "grid override";
    if (!(o.voxelSize > 0.0) || !std::isfinite(o.voxelSize))
        throw InputError(what, "voxel_size", "must be a positive number, got " + number(o.voxelSize));
    GridSpec spec;
    spec.origin = o.min;
    spec.voxelSize = o.voxelSize;
    int* n[3] = {&spec.nx, &spec.ny, &spec.nz};
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(o.min[a]) || !std::isfinite(o.max[a]) || !(o.max[a] > o.min[a]))
            throw InputError(what, "bounds", "max must exceed min on every axis (axis " + std::string(1, "xyz"[a]) +
                                                 ": " + number(o.min[a]) + " .. " + number(o.max[a]) + ")");
        const double cells = std::ceil((o.max[a] - o.min[a]) / o.voxelSize);
        if (cells > double(vdbbake::kMaxDenseVoxels))
            throw InputError(what, "voxel_size", "grid too large along " + std::string(1, "xyz"[a]));
        *n[a] = int(cells);
    }
    return spec;
}

}  // namespace

VolumeTarget loadVolumeTarget(const std::vector<TargetVolumeSpec>& specs, const GridOverride* grid) {
    initOpenVdb();
    if (specs.empty()) throw InputError("targets", "", "no volume target given");
    std::vector<openvdb::FloatGrid::Ptr> grids;
    VolumeTarget target;
    for (const TargetVolumeSpec& s : specs) grids.push_back(readLevelSet(s.path, target.fileHashes.emplace_back()));

    if (grid) {
        target.grid = overrideGrid(*grid);
    } else {
        openvdb::BBoxd bounds = vdbbake::activeWorldBounds(*grids[0]);
        for (std::size_t i = 1; i < grids.size(); ++i) bounds.expand(vdbbake::activeWorldBounds(*grids[i]));
        const openvdb::math::Transform& first = grids[0]->transform();
        const openvdb::Vec3d vs = first.voxelSize();
        const double voxelSize = std::min({vs[0], vs[1], vs[2]});  // uniform for our files
        // Corners of the first target's voxels, so dense centres coincide with its voxel centres.
        const openvdb::Vec3d anchor = first.indexToWorld(openvdb::Vec3d(-0.5));
        target.grid = vdbbake::paddedGrid(bounds, voxelSize, anchor);
    }
    const GridSpec& g = target.grid;
    const double voxels = double(g.nx) * double(g.ny) * double(g.nz);  // no overflow
    if (voxels > double(vdbbake::kMaxDenseVoxels))
        throw InputError(grid ? "grid override" : specs[0].path, "",
                         "dense target grid of " + std::to_string(g.nx) + " x " + std::to_string(g.ny) + " x " +
                             std::to_string(g.nz) + " voxels is too large; use a coarser voxel size");

    target.fill.assign(g.words(), 0);
    target.avoid.assign(g.words(), 0);
    for (std::size_t i = 0; i < specs.size(); ++i)
        vdbbake::bakeInside(*grids[i], g, specs[i].avoid ? target.avoid : target.fill);
    target.fillCount = vdbbake::popcount(target.fill);
    target.avoidCount = vdbbake::popcount(target.avoid);
    target.hash = vdbbake::targetHash(target);
    return target;
}

}  // namespace shapevo
