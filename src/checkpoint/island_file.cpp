// Island files (island-RRRR.h5): one island's state in HDF5. The names below are a stable public
// format (docs/run-folder.md, `h5ls -r`, `h5dump -H`); change them only with a new schema_version.
//
//   /                         root group, attributes:
//       schema_version        u32   format version of this layout (4; 3 lacks /migrants)
//       run_id                string  the run this island belongs to (as in run.h5)
//       seed                  u64   the run's seed (as in run.h5)
//       ranks                 i32   islands in the run (as in run.h5)
//       rank                  i32   the island (MPI rank) this file belongs to
//       generation            u32   generations completed
//       evaluations           u64   fitness evaluations on this island so far
//       individuals           u64   population size (N)
//   /population/genes         u32 [W]      every chromosome's words, concatenated in order
//   /population/offsets       u64 [N+1]    word offset of each chromosome's start in genes; the
//                                          last entry is W (chromosome i = words [o[i], o[i+1]))
//   /population/gene_counts   u32 [N]      genes in each chromosome
//   /population/fitness       f64 [N]      fitness of each individual
//   /rng/state                u64 [4]      the island's xoshiro256** state
//   /migrants/genes, /migrants/offsets, /migrants/gene_counts, /migrants/fitness
//                                          (schema 4) the migrants received from rank - 1 that
//                                          join at the next migration generation (sync mode
//                                          completes each exchange one migration late), laid out
//                                          as the population; M = offsets - 1, often 0
//   /curve                    f64 [G x 7]  this island's fitness curve, one row per generation,
//                                          chunked and extendible (G unlimited); attribute
//       columns               string "generation,seconds,evaluations,best,mean,std,iou"
//
// Every dataset has an attribute "xxh3_64" (u64): XXH3-64 of its raw little-endian bytes; the
// root attribute attributes_xxh3_64 covers every other attribute (hdf5_file.hpp).
// All numbers are stored little-endian. Reading checks types and shapes, every checksum (naming
// the dataset that does not match), and then the content (island_codec.cpp): offsets start at 0,
// never decrease and end at W, counts match N, each chromosome is a valid derivation of the
// grammar within the genome limits, fitness values are finite.
#include "checkpoint/checkpoint_file.hpp"
#include "checkpoint/hdf5_file.hpp"
#include "checkpoint/island_codec.hpp"
#include "base/input_error.hpp"

namespace shapevo {

void writeIslandFile(const std::string& path, const IslandState& s) {
    using namespace island_layout;
    const IslandBytes b = encodeIsland(s);
    h5::H5Writer w(path);
    w.attribute(w.root(), "schema_version", kCheckpointSchemaVersion);
    w.attribute(w.root(), "run_id", s.runId);
    w.attribute(w.root(), "seed", s.seed);
    w.attribute(w.root(), "ranks", s.ranks);
    w.attribute(w.root(), "rank", b.rank);
    w.attribute(w.root(), "generation", b.generation);
    w.attribute(w.root(), "evaluations", b.evaluations);
    w.attribute(w.root(), "individuals", b.individuals);
    {
        h5::Handle population = w.group(w.root(), "population");
        const hsize_t words[] = {b.genes.size() / 4}, offsets[] = {b.individuals + 1}, n[] = {b.individuals};
        w.dataset(population.get(), "genes", H5T_STD_U32LE, b.genes, words);
        w.dataset(population.get(), "offsets", H5T_STD_U64LE, b.offsets, offsets);
        w.dataset(population.get(), "gene_counts", H5T_STD_U32LE, b.geneCounts, n);
        w.dataset(population.get(), "fitness", H5T_IEEE_F64LE, b.fitness, n);
    }
    {
        h5::Handle migrants = w.group(w.root(), "migrants");
        const hsize_t words[] = {b.arrivalGenes.size() / 4}, offsets[] = {b.arrivalOffsets.size() / 8},
                      m[] = {b.arrivalFitness.size() / 8};
        w.dataset(migrants.get(), "genes", H5T_STD_U32LE, b.arrivalGenes, words);
        w.dataset(migrants.get(), "offsets", H5T_STD_U64LE, b.arrivalOffsets, offsets);
        w.dataset(migrants.get(), "gene_counts", H5T_STD_U32LE, b.arrivalGeneCounts, m);
        w.dataset(migrants.get(), "fitness", H5T_IEEE_F64LE, b.arrivalFitness, m);
    }
    {
        h5::Handle rng = w.group(w.root(), "rng");
        const hsize_t four[] = {4};
        w.dataset(rng.get(), "state", H5T_STD_U64LE, b.rng, four);
    }
    const hsize_t curve[] = {s.curve.size(), kCurveWidth};
    {
        h5::Handle d = w.dataset(w.root(), "curve", H5T_IEEE_F64LE, b.curve, curve, /*extendible=*/true);
        w.attribute(d.get(), "columns", std::string(kCurveColumns));
    }
    w.finish();
}

IslandState readIslandFile(const std::string& path, const GenomeFamily& family, const GenomeLimits& limits) {
    using namespace island_layout;
    const h5::H5Reader r(path, kOldestReadableSchemaVersion, kCheckpointSchemaVersion);
    const bool schema2 = r.schema() == 2;  // its curve has no iou column
    IslandBytes b;
    b.rank = r.i32("/", "rank");
    b.generation = r.u32("/", "generation");
    b.evaluations = r.u64("/", "evaluations");
    b.individuals = r.u64("/", "individuals");
    b.genes = r.dataset(kGenes, H5T_STD_U32LE, 1);
    b.offsets = r.dataset(kOffsets, H5T_STD_U64LE, 1);
    b.geneCounts = r.dataset(kGeneCounts, H5T_STD_U32LE, 1);
    b.fitness = r.dataset(kFitness, H5T_IEEE_F64LE, 1);
    b.rng = r.dataset(kRng, H5T_STD_U64LE, 1);
    if (r.schema() >= 4) {
        b.arrivalGenes = r.dataset(kArrivalGenes, H5T_STD_U32LE, 1);
        b.arrivalOffsets = r.dataset(kArrivalOffsets, H5T_STD_U64LE, 1);
        b.arrivalGeneCounts = r.dataset(kArrivalGeneCounts, H5T_STD_U32LE, 1);
        b.arrivalFitness = r.dataset(kArrivalFitness, H5T_IEEE_F64LE, 1);
    }
    b.curveWidth = schema2 ? kCurveWidthSchema2 : kCurveWidth;
    b.curve = r.dataset(kCurve, H5T_IEEE_F64LE, 2, b.curveWidth);
    const char* columns = schema2 ? kCurveColumnsSchema2 : kCurveColumns;
    if (r.string(kCurve, "columns") != columns)
        throw InputError(path, std::string(kCurve) + "@columns", std::string("expected \"") + columns + "\"");
    IslandState s = decodeIsland(b.view(), family, limits, path);
    s.runId = r.string("/", "run_id");
    s.seed = r.u64("/", "seed");
    s.ranks = r.i32("/", "ranks");
    return s;
}

}  // namespace shapevo
