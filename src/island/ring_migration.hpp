// RingMigration: every `interval` generations each island sends its best `count` individuals
// (packed chromosome words plus fitness) to rank + 1, where they replace the worst.
// Synchronous (lock-step, repeatable) by default; asynchronous mode posts non-blocking sends
// and takes whatever has arrived, and never blocks (finish() drains without deadlock).
// Received bytes are untrusted: every chromosome is validated before it joins the population.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "genome/chromosome.hpp"
#include "island/mpi_session.hpp"
#include "island/migration_settings.hpp"
#include "island/posted_sends.hpp"
#include "search/population.hpp"

namespace shapevo {

/// [count] then per individual: [fitness bits lo][hi][genes][words][words...]
void packIndividuals(const Population& pop, const std::vector<std::size_t>& which, std::vector<std::uint32_t>& out);
/// Append the individuals in `in` to `chromosomes`/`fitness`; "" on success, else what is wrong.
std::string unpackIndividuals(const Grammar& g, const GenomeLimits& limits, const std::vector<std::uint32_t>& in,
                              std::vector<Chromosome>& chromosomes, std::vector<double>& fitness);
/// Indices of the `count` best individuals, best first (ties: lower index first).
std::vector<std::size_t> bestIndices(const Population& pop, std::size_t count);
/// Replace the worst individuals (ties: higher index first) by the arrivals.
void replaceWorst(Population& pop, const std::vector<Chromosome>& arrivals, const std::vector<double>& fitness);

class RingMigration {
public:
    RingMigration(const MpiSession& mpi, const MigrationSettings& settings, const Grammar& g, const GenomeLimits& limits);
    /// Call after generation `generation` completes; migrates if it is a migration generation.
    void afterGeneration(Population& pop, std::uint32_t generation);
    /// Async mode: complete every send and discard late arrivals; collective, call on all ranks.
    void finish();
    std::uint64_t received() const { return received_; }
    std::uint64_t rejected() const { return rejected_; }

private:
    void integrate(Population& pop, const std::vector<std::uint32_t>& words);

    const MpiSession& mpi_;
    MigrationSettings settings_;
    const Grammar& grammar_;
    GenomeLimits limits_;
    std::vector<std::uint32_t> outgoing_, incoming_;
    std::vector<Chromosome> arrivals_;
    std::vector<double> arrivalFitness_;
    PostedSends sends_;
    std::uint64_t received_ = 0, rejected_ = 0;
};

}  // namespace shapevo
