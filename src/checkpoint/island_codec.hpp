// Island codec: an IslandState as the raw little-endian bytes of its datasets, and back.
// The decoder is where an island's content is validated (shapes, offsets, every chromosome
// by its model family's check(), finite fitness, representable curve values); island_file.cpp only moves
// these bytes between memory and HDF5 and checks their checksums. Keeping the decoder free of
// HDF5 lets the fuzzer (tests/fuzz/fuzz_checkpoint_reader.cpp) feed it arbitrary bytes directly.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "checkpoint/island_state.hpp"
#include "genome/chromosome.hpp"
#include "genome/genome_family.hpp"

namespace shapevo {

/// Dataset names of an island file, also used as the "where" of decoding errors.
namespace island_layout {
inline constexpr const char* kGenes = "/population/genes";
inline constexpr const char* kOffsets = "/population/offsets";
inline constexpr const char* kGeneCounts = "/population/gene_counts";
inline constexpr const char* kFitness = "/population/fitness";
inline constexpr const char* kRng = "/rng/state";
// Schema 4: migrants received from rank - 1 that join at the next migration generation (sync mode).
inline constexpr const char* kArrivalGenes = "/migrants/genes";
inline constexpr const char* kArrivalOffsets = "/migrants/offsets";
inline constexpr const char* kArrivalGeneCounts = "/migrants/gene_counts";
inline constexpr const char* kArrivalFitness = "/migrants/fitness";
inline constexpr const char* kCurve = "/curve";
inline constexpr const char* kCurveColumns = "generation,seconds,evaluations,best,mean,std,iou";
inline constexpr std::size_t kCurveWidth = 7;  ///< schema 3 (schema 2 had 6 columns, without iou)
inline constexpr const char* kCurveColumnsSchema2 = "generation,seconds,evaluations,best,mean,std";
inline constexpr std::size_t kCurveWidthSchema2 = 6;
}  // namespace island_layout

/// Borrowed raw bytes of one island's datasets (little endian) plus its root attributes.
struct IslandBytesView {
    std::int32_t rank = 0;
    std::uint32_t generation = 0;
    std::uint64_t evaluations = 0;
    std::uint64_t individuals = 0;
    std::span<const std::uint8_t> genes;       ///< u32 words of every chromosome, concatenated
    std::span<const std::uint8_t> offsets;     ///< u64 x (individuals + 1): word offset of each start
    std::span<const std::uint8_t> geneCounts;  ///< u32 x individuals
    std::span<const std::uint8_t> fitness;     ///< f64 x individuals
    std::span<const std::uint8_t> rng;         ///< u64 x 4
    std::span<const std::uint8_t> curve;       ///< f64 x rows x curveWidth
    std::size_t curveWidth = island_layout::kCurveWidth;  ///< 7, or 6 in a schema 2 file (no iou)
    /// The arrivals, laid out as the population (their count is the offsets' minus one); all four
    /// empty in files before schema 4 (no arrivals).
    std::span<const std::uint8_t> arrivalGenes, arrivalOffsets, arrivalGeneCounts, arrivalFitness;
};

/// Owned raw bytes of one island's datasets, as encodeIsland makes them.
struct IslandBytes {
    std::int32_t rank = 0;
    std::uint32_t generation = 0;
    std::uint64_t evaluations = 0;
    std::uint64_t individuals = 0;
    std::vector<std::uint8_t> genes, offsets, geneCounts, fitness, rng, curve;
    std::size_t curveWidth = island_layout::kCurveWidth;
    std::vector<std::uint8_t> arrivalGenes, arrivalOffsets, arrivalGeneCounts, arrivalFitness;
    IslandBytesView view() const {
        return {rank,  generation, evaluations, individuals,  genes,        offsets,           geneCounts,
                fitness, rng,      curve,       curveWidth,   arrivalGenes, arrivalOffsets, arrivalGeneCounts,
                arrivalFitness};
    }
};

/// Encode a state. Throws std::invalid_argument for a state that could not be read back (fitness
/// count differs from the population size, non-finite fitness, a curve value that does not fit),
/// so such a bug shows when the checkpoint is written, not when a run is resumed.
IslandBytes encodeIsland(const IslandState& s);

/// Decode and validate, every chromosome with family.check(). Throws InputError(path, dataset
/// name, what is wrong).
IslandState decodeIsland(const IslandBytesView& v, const GenomeFamily& family, const GenomeLimits& limits,
                         const std::string& path);

/// A curve as rows of 7 little-endian f64 (generation, seconds, evaluations, best, mean, std, iou).
std::vector<std::uint8_t> encodeCurve(const std::vector<GenerationStats>& curve);
/// Throws InputError(path, where, ...) unless `bytes` is whole rows whose generation and
/// evaluations columns are non-negative integers that fit their types. `width` is the row's
/// column count: kCurveWidth, or kCurveWidthSchema2 for a schema 2 file (its iou is NaN).
std::vector<GenerationStats> decodeCurve(std::span<const std::uint8_t> bytes, const std::string& path,
                                         const std::string& where, std::size_t width = island_layout::kCurveWidth);

}  // namespace shapevo
