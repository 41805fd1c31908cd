// writeVdbGrid: one OpenVDB grid written as a .vdb file atomically (base/atomic_write.hpp: a
// temporary file, then a rename), for every VDB file shapevo writes (targets from meshes, a
// model's voxels). Promises: the file is complete or absent; a failure is one InputError naming
// the path ("cannot write: ..."); with Replace::Never an existing file is never replaced.
#pragma once
#include <exception>
#include <string>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include "base/atomic_write.hpp"
#include "base/input_error.hpp"

namespace shapevo {

inline void writeVdbGrid(const openvdb::GridBase::ConstPtr& grid, const std::string& path, Replace replace = Replace::Always) {
    writeAtomically(
        path,
        [&](const std::string& temp) {
            try {
                openvdb::io::File file(temp);
                file.write(openvdb::GridCPtrVec{grid});
                file.close();
            } catch (const std::exception& e) {
                throw InputError(path, "", std::string("cannot write: ") + e.what());
            }
        },
        replace);
}

}  // namespace shapevo
