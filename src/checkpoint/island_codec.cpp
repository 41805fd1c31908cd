// Island codec: IslandState <-> raw little-endian dataset bytes, with every content check of the
// checkpoint reader (see island_codec.hpp). Sizes are checked against each other before anything
// is allocated, so lying counts cannot make the reader allocate more than the bytes it was given.
#include "checkpoint/island_codec.hpp"

#include <limits>

#include <cmath>
#include <stdexcept>

#include "base/little_endian.hpp"
#include "genome/genome_family.hpp"
#include "base/input_error.hpp"

namespace shapevo {

namespace {

using namespace island_layout;

/// Integers in the curve are stored as f64; 2^53 is the largest bound below which all are exact.
constexpr double kMaxExactInteger = 9007199254740992.0;

std::string count(std::size_t n, const char* what) { return std::to_string(n) + " " + what; }

/// Number of `width`-byte elements in `bytes`, or an InputError if it is not whole elements.
std::size_t elements(std::span<const std::uint8_t> bytes, std::size_t width, const std::string& path, const char* where,
                     const char* type) {
    if (bytes.size() % width != 0)
        throw InputError(path, where, count(bytes.size(), "bytes is not a whole number of ") + type + " values");
    return bytes.size() / width;
}

void expectElements(std::span<const std::uint8_t> bytes, std::size_t width, std::uint64_t expected,
                    const std::string& path, const char* where, const char* type, const char* why) {
    const std::size_t n = elements(bytes, width, path, where, type);
    if (n != expected)
        throw InputError(path, where, "holds " + count(n, type) + " values, expected " + std::to_string(expected) + " (" +
                                          why + ")");
}

/// An integer column of the curve: finite, whole, within [0, max].
bool wholeInRange(double v, double max) { return std::isfinite(v) && v >= 0 && v <= max && std::floor(v) == v; }

}  // namespace

std::vector<std::uint8_t> encodeCurve(const std::vector<GenerationStats>& curve) {
    std::vector<std::uint8_t> out;
    out.reserve(curve.size() * kCurveWidth * 8);
    for (const GenerationStats& row : curve) {
        if (double(row.evaluations) > kMaxExactInteger)
            throw std::invalid_argument("curve: " + std::to_string(row.evaluations) +
                                        " evaluations cannot be stored exactly as f64");
        for (double v : {double(row.generation), row.seconds, double(row.evaluations), row.best, row.mean, row.std, row.iou})
            le::append(out, v);
    }
    return out;
}

std::vector<GenerationStats> decodeCurve(std::span<const std::uint8_t> bytes, const std::string& path,
                                         const std::string& where, std::size_t width) {
    if (width != kCurveWidth && width != kCurveWidthSchema2) throw std::invalid_argument("decodeCurve: bad width");
    const std::size_t kRowBytes = width * 8;
    if (bytes.size() % kRowBytes != 0)
        throw InputError(path, where, std::to_string(bytes.size()) + " bytes is not a whole number of " +
                                          std::to_string(width) + "-column f64 rows");
    std::vector<GenerationStats> curve(bytes.size() / kRowBytes);
    for (std::size_t i = 0; i < curve.size(); ++i) {
        const std::uint8_t* p = bytes.data() + i * kRowBytes;
        double v[kCurveWidth];
        v[kCurveWidth - 1] = std::numeric_limits<double>::quiet_NaN();  // schema 2: no iou column
        for (std::size_t k = 0; k < width; ++k) v[k] = le::load<double>(p + 8 * k);
        if (!wholeInRange(v[0], 4294967295.0))
            throw InputError(path, where, "row " + std::to_string(i) + ": generation is not a whole number in [0, 2^32)");
        if (!wholeInRange(v[2], kMaxExactInteger))
            throw InputError(path, where, "row " + std::to_string(i) + ": evaluations is not a whole number in [0, 2^53]");
        curve[i] = {std::uint32_t(v[0]), v[1], std::uint64_t(v[2]), v[3], v[4], v[5], v[6]};
    }
    return curve;
}

namespace {

/// A population's four datasets: every chromosome's words, offsets, gene counts, fitness.
void encodePopulation(const Population& pop, const std::string& owner, std::vector<std::uint8_t>& genes,
                      std::vector<std::uint8_t>& offsets, std::vector<std::uint8_t>& geneCounts,
                      std::vector<std::uint8_t>& fitness) {
    if (pop.fitness.size() != pop.individuals.size())
        throw std::invalid_argument(owner + ": " + count(pop.fitness.size(), "fitness values") + " for " +
                                    count(pop.individuals.size(), "individuals"));
    std::size_t words = 0;
    for (const Chromosome& c : pop.individuals) words += c.words.size();
    genes.reserve(words * 4);
    offsets.reserve((pop.size() + 1) * 8);
    le::append(offsets, std::uint64_t(0));
    for (std::size_t i = 0; i < pop.size(); ++i) {
        const Chromosome& c = pop.individuals[i];
        for (std::uint32_t w : c.words) le::append(genes, w);
        le::append(offsets, std::uint64_t(genes.size() / 4));
        le::append(geneCounts, c.genes);
        if (!std::isfinite(pop.fitness[i]))
            throw std::invalid_argument(owner + ": fitness of individual " + std::to_string(i) + " is not finite");
        le::append(fitness, pop.fitness[i]);
    }
}

}  // namespace

IslandBytes encodeIsland(const IslandState& s) {
    const std::string owner = "island " + std::to_string(s.rank);
    IslandBytes b;
    b.rank = s.rank;
    b.generation = s.generation;
    b.evaluations = s.evaluations;
    b.individuals = s.population.size();
    encodePopulation(s.population, owner, b.genes, b.offsets, b.geneCounts, b.fitness);
    encodePopulation(s.arrivals, owner + " arrivals", b.arrivalGenes, b.arrivalOffsets, b.arrivalGeneCounts,
                     b.arrivalFitness);
    for (std::uint64_t w : s.rng) le::append(b.rng, w);
    b.curve = encodeCurve(s.curve);
    return b;
}

namespace {

struct PopulationView {
    std::span<const std::uint8_t> genes, offsets, geneCounts, fitness;
    const char *genesName, *offsetsName, *geneCountsName, *fitnessName;
};

/// Decode and validate `individuals` individuals (shapes, offsets, values, then every chromosome
/// as a genome of the family: its check()). Throws InputError naming the dataset.
Population decodePopulation(const PopulationView& v, std::uint64_t individuals, const GenomeFamily& family,
                            const GenomeLimits& limits, const std::string& path) {
    // 1. Shapes, all against the count, before anything is allocated.
    const std::size_t offsets = elements(v.offsets, 8, path, v.offsetsName, "u64");
    if (offsets == 0 || offsets - 1 != individuals)
        throw InputError(path, v.offsetsName, "holds " + count(offsets, "u64") + " values, expected individuals + 1 = " +
                                                  std::to_string(individuals) + " + 1 (the start of each and the end)");
    expectElements(v.geneCounts, 4, individuals, path, v.geneCountsName, "u32", "one per individual");
    expectElements(v.fitness, 8, individuals, path, v.fitnessName, "f64", "one per individual");
    const std::size_t words = elements(v.genes, 4, path, v.genesName, "u32");

    // 2. Offsets: start at 0, never decrease, end at the number of words; no chromosome over 2^32 words.
    const std::size_t n = std::size_t(individuals);
    auto offset = [&](std::size_t i) { return le::load<std::uint64_t>(v.offsets.data() + 8 * i); };
    if (offset(0) != 0) throw InputError(path, v.offsetsName, "first offset is " + std::to_string(offset(0)) + ", not 0");
    for (std::size_t i = 0; i < n; ++i) {
        if (offset(i + 1) < offset(i))
            throw InputError(path, v.offsetsName,
                             "offset " + std::to_string(i + 1) + " is smaller than offset " + std::to_string(i));
        if (offset(i + 1) - offset(i) > UINT32_MAX)
            throw InputError(path, v.offsetsName, "individual " + std::to_string(i) + " spans more than 2^32 words");
    }
    if (offset(n) != words)
        throw InputError(path, v.offsetsName, "last offset is " + std::to_string(offset(n)) + " but " + v.genesName +
                                                  " holds " + count(words, "words"));

    // 3. Values: fitness finite, gene counts within the limit (cheap, before validating trees).
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(le::load<double>(v.fitness.data() + 8 * i)))
            throw InputError(path, v.fitnessName, "fitness of individual " + std::to_string(i) + " is not finite");
        const std::uint32_t genes = le::load<std::uint32_t>(v.geneCounts.data() + 4 * i);
        if (genes > limits.maxGenes)
            throw InputError(path, v.geneCountsName, "individual " + std::to_string(i) + " has " + count(genes, "genes") +
                                                         ", over the limit of " + std::to_string(limits.maxGenes));
    }

    // 4. Build, validating every chromosome as a genome of the family (a tree: a derivation of the grammar).
    Population pop;
    pop.individuals.resize(n);
    pop.fitness.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        Chromosome& c = pop.individuals[i];
        c.genes = le::load<std::uint32_t>(v.geneCounts.data() + 4 * i);
        c.words.resize(std::size_t(offset(i + 1) - offset(i)));
        for (std::size_t w = 0; w < c.words.size(); ++w)
            c.words[w] = le::load<std::uint32_t>(v.genes.data() + 4 * (std::size_t(offset(i)) + w));
        const std::string problem = family.check(c, limits);
        if (!problem.empty()) throw InputError(path, v.genesName, "individual " + std::to_string(i) + ": " + problem);
        pop.fitness[i] = le::load<double>(v.fitness.data() + 8 * i);
    }
    return pop;
}

}  // namespace

IslandState decodeIsland(const IslandBytesView& v, const GenomeFamily& family, const GenomeLimits& limits,
                         const std::string& path) {
    expectElements(v.rng, 8, 4, path, kRng, "u64", "the xoshiro256** state");
    IslandState s;
    s.rank = v.rank;
    s.generation = v.generation;
    s.evaluations = v.evaluations;
    s.population = decodePopulation({v.genes, v.offsets, v.geneCounts, v.fitness, kGenes, kOffsets, kGeneCounts, kFitness},
                                    v.individuals, family, limits, path);
    const bool arrivals = !(v.arrivalGenes.empty() && v.arrivalOffsets.empty() && v.arrivalGeneCounts.empty() &&
                            v.arrivalFitness.empty());
    if (arrivals)  // as many as the offsets say: each is validated like the population
        s.arrivals = decodePopulation({v.arrivalGenes, v.arrivalOffsets, v.arrivalGeneCounts, v.arrivalFitness, kArrivalGenes,
                                       kArrivalOffsets, kArrivalGeneCounts, kArrivalFitness},
                                      v.arrivalOffsets.size() / 8 == 0 ? 0 : v.arrivalOffsets.size() / 8 - 1, family, limits, path);
    for (std::size_t k = 0; k < 4; ++k) s.rng[k] = le::load<std::uint64_t>(v.rng.data() + 8 * k);
    s.curve = decodeCurve(v.curve, path, kCurve, v.curveWidth);
    return s;
}

}  // namespace shapevo
