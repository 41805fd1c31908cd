// RingMigration: every `interval` generations each island sends its best `count` individuals
// (packed chromosome words plus fitness) to rank + 1, where they replace the worst (who leaves and
// who is replaced, ties included: the migration policy, search/migration_policy.hpp, which the
// hybrid search's in-process ring follows too).
// Sync mode (repeatable) completes each exchange one migration late: the migrants sent at
// generation g join the neighbour at its generation g + interval, so an island waits only when
// its left neighbour is a whole interval behind, never for the scheduler's small delays (4 ranks
// on 2 cores). Migrants received but not yet joined are part of the island's state: a checkpoint
// stores them (arrivals()), a resume gives them back (restoreArrivals()).
// Async mode posts non-blocking sends and takes whatever has arrived, and never blocks.
// finish() drains both without deadlock. Received bytes are untrusted: every chromosome is
// validated (its model family's check(), genome/genome_family.hpp) before it joins the population.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "genome/chromosome.hpp"
#include "genome/genome_family.hpp"
#include "island/mpi_session.hpp"
#include "island/migration_settings.hpp"
#include "island/posted_sends.hpp"
#include "search/migration_policy.hpp"
#include "search/population.hpp"

namespace shapevo {

/// [count] then per individual: [fitness bits lo][hi][genes][words][words...]
void packIndividuals(const Population& pop, const std::vector<std::size_t>& which, std::vector<std::uint32_t>& out);
/// Append the individuals in `in` to `chromosomes`/`fitness`, each checked by `family`; "" on
/// success, else what is wrong.
std::string unpackIndividuals(const GenomeFamily& family, const GenomeLimits& limits, const std::vector<std::uint32_t>& in,
                              std::vector<Chromosome>& chromosomes, std::vector<double>& fitness);

class RingMigration {
public:
    /// Migrants are genomes of `family` (which must outlive this) within `limits`.
    RingMigration(const MpiSession& mpi, const MigrationSettings& settings, const GenomeFamily& family,
                  const GenomeLimits& limits);
    /// Call after generation `generation` completes; migrates if it is a migration generation.
    /// Arrivals replace the worst of the first `slots` individuals (SearchMethod::migrantSlots).
    void afterGeneration(Population& pop, std::uint32_t generation, std::size_t slots);
    /// Sync mode, collective: receive the migrants still in flight to this rank and return every
    /// one not yet joined (for a checkpoint). Empty in async mode.
    const Population& arrivals();
    /// Sync mode: migrants a checkpoint held, to join at the next migration generation.
    void restoreArrivals(const Population& arrivals);
    /// Complete every send and discard what has not joined; collective, call on all ranks.
    void finish();
    std::uint64_t received() const { return received_; }
    std::uint64_t rejected() const { return rejected_; }

private:
    /// Validate a message into `into` (empty and counted as rejected if it is bad).
    bool unpack(const std::vector<std::uint32_t>& words, Population& into);
    /// Replace the worst of the first `slots` of `pop` by arrived_, and empty it.
    void joinArrived(Population& pop, std::size_t slots);
    void receiveInFlight();  ///< sync: the message of the last migration generation, into arrived_

    const MpiSession& mpi_;
    MigrationSettings settings_;
    const GenomeFamily& family_;
    GenomeLimits limits_;
    std::vector<std::uint32_t> outgoing_, incoming_;
    PostedSends sends_;
    bool inFlight_ = false;  ///< sync: a message from the left neighbour is on its way
    Population arrived_;     ///< received and validated; sync: joining at the next migration generation
    std::uint64_t received_ = 0, rejected_ = 0;
};

}  // namespace shapevo
