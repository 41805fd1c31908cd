// Model volume: Voxelizer bit rows -> OpenVDB fog volume with the dense grid's transform.
#include "score/volume/model_volume.hpp"

#include <bit>
#include <cmath>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include "base/atomic_write.hpp"
#include "base/input_error.hpp"
#include "score/volume/vdb_write.hpp"
#include "score/volume/voxelizer.hpp"

namespace shapevo {

namespace {

openvdb::FloatGrid::Ptr modelGrid(const Geometry& geometry, const GridSpec& grid) {
    Voxelizer voxelizer(grid);
    VoxelCounts counts;
    for (const Primitive& p : geometry.primitives) voxelizer.add(p, geometry.meshes, counts);
    const std::vector<std::uint64_t>& bits = voxelizer.occupancy();

    openvdb::FloatGrid::Ptr out = openvdb::FloatGrid::create(0.0f);
    // openvdb places voxel centres at integer index coordinates: index 0 sits at origin + vs / 2.
    openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(grid.voxelSize);
    xform->postTranslate(openvdb::Vec3d(grid.origin.x, grid.origin.y, grid.origin.z) + openvdb::Vec3d(0.5 * grid.voxelSize));
    out->setTransform(xform);
    openvdb::FloatGrid::Accessor acc = out->getAccessor();
    const std::size_t W = std::size_t(grid.wordsPerRow());
    for (int z = 0; z < grid.nz; ++z)
        for (int y = 0; y < grid.ny; ++y) {
            const std::uint64_t* row = &bits[(std::size_t(z) * std::size_t(grid.ny) + std::size_t(y)) * W];
            for (std::size_t w = 0; w < W; ++w)
                for (std::uint64_t word = row[w]; word != 0; word &= word - 1)
                    acc.setValueOn(openvdb::Coord(int(w * 64) + std::countr_zero(word), y, z), 1.0f);
        }
    voxelizer.clear();

    out->setName("density");
    out->setGridClass(openvdb::GRID_FOG_VOLUME);
    out->insertMeta("source", openvdb::StringMetadata("shapevo model"));
    out->insertMeta("shapevo_role", openvdb::StringMetadata("model"));
    out->insertMeta("voxel_size", openvdb::DoubleMetadata(grid.voxelSize));
    out->insertMeta("primitives", openvdb::Int64Metadata(openvdb::Int64(geometry.primitives.size())));
    return out;
}

}  // namespace

void writeModelVdb(const Geometry& geometry, const GridSpec& grid, const std::string& path) {
    if (grid.nx <= 0 || grid.ny <= 0 || grid.nz <= 0 || !(grid.voxelSize > 0.0) || !std::isfinite(grid.voxelSize))
        throw InputError(path, "", "cannot voxelize the model: the target grid is empty");
    openvdb::initialize();
    const openvdb::FloatGrid::Ptr vdb = modelGrid(geometry, grid);
    writeVdbGrid(vdb, path);
}

}  // namespace shapevo
