// Ring migration: packing, validation, sync exchange completed one migration late (posted sends,
// a polite probe), async with posted sends and Iprobe.
#include "island/ring_migration.hpp"

#include <bit>
#include <cmath>
#include <cstring>

#include <mpi.h>

#include "island/drain.hpp"
#include "island/polite_wait.hpp"

namespace shapevo {

namespace {
constexpr int kMigrationTag = 72;

/// Has a migration message from `source` arrived (MPI_Iprobe)? Its envelope in `status`.
bool arrivedFrom(int source, MPI_Status& status) {
    int arrived = 0;
    MPI_Iprobe(source, kMigrationTag, MPI_COMM_WORLD, &arrived, &status);
    return arrived != 0;
}

/// Receive the message whose envelope `status` describes into `words`.
void take(int source, const MPI_Status& status, std::vector<std::uint32_t>& words) {
    int count = 0;
    MPI_Get_count(&status, MPI_UINT32_T, &count);
    words.resize(std::size_t(count));
    MPI_Recv(words.data(), count, MPI_UINT32_T, source, kMigrationTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
}
}  // namespace


void packIndividuals(const Population& pop, const std::vector<std::size_t>& which, std::vector<std::uint32_t>& out) {
    out.clear();
    out.push_back(std::uint32_t(which.size()));
    for (std::size_t i : which) {
        const std::uint64_t bits = std::bit_cast<std::uint64_t>(pop.fitness[i]);
        const Chromosome& c = pop.individuals[i];
        out.push_back(std::uint32_t(bits));
        out.push_back(std::uint32_t(bits >> 32));
        out.push_back(c.genes);
        out.push_back(c.size());
        out.insert(out.end(), c.words.begin(), c.words.end());
    }
}

std::string unpackIndividuals(const GenomeFamily& family, const GenomeLimits& limits, const std::vector<std::uint32_t>& in,
                              std::vector<Chromosome>& chromosomes, std::vector<double>& fitness) {
    if (in.empty()) return "empty message";
    std::size_t pos = 1;
    for (std::uint32_t k = 0; k < in[0]; ++k) {
        if (pos + 4 > in.size()) return "truncated header of individual " + std::to_string(k);
        const double f = std::bit_cast<double>(std::uint64_t(in[pos]) | (std::uint64_t(in[pos + 1]) << 32));
        const std::uint32_t genes = in[pos + 2], words = in[pos + 3];
        pos += 4;
        if (words > in.size() - pos) return "truncated chromosome " + std::to_string(k);
        Chromosome c;
        c.genes = genes;
        c.words.assign(in.begin() + std::ptrdiff_t(pos), in.begin() + std::ptrdiff_t(pos + words));
        pos += words;
        if (const std::string e = family.check(c, limits); !e.empty()) return "individual " + std::to_string(k) + ": " + e;
        if (!std::isfinite(f)) return "individual " + std::to_string(k) + ": fitness is not finite";
        chromosomes.push_back(std::move(c));
        fitness.push_back(f);
    }
    return pos == in.size() ? "" : "trailing words";
}

RingMigration::RingMigration(const MpiSession& mpi, const MigrationSettings& settings, const GenomeFamily& family,
                             const GenomeLimits& limits)
    : mpi_(mpi), settings_(settings), family_(family), limits_(limits) {}


bool RingMigration::unpack(const std::vector<std::uint32_t>& words, Population& into) {
    into.individuals.clear();
    into.fitness.clear();
    if (unpackIndividuals(family_, limits_, words, into.individuals, into.fitness).empty()) return true;
    ++rejected_;  // never let bad bytes into the population
    into.individuals.clear();
    into.fitness.clear();
    return false;
}

void RingMigration::joinArrived(Population& pop, std::size_t slots) {
    received_ += arrived_.size();
    replaceWorst(pop, arrived_.individuals, arrived_.fitness, slots);
    arrived_.individuals.clear();
    arrived_.fitness.clear();
}

void RingMigration::afterGeneration(Population& pop, std::uint32_t generation, std::size_t slots) {
    if (!mpi_.active() || mpi_.size() < 2 || settings_.interval == 0 || settings_.count == 0) return;
    if (generation % settings_.interval != 0) return;
    const int right = (mpi_.rank() + 1) % mpi_.size(), left = (mpi_.rank() + mpi_.size() - 1) % mpi_.size();
    packIndividuals(pop, bestIndices(pop, settings_.count), outgoing_);
    // Sync: the migrants of the last migration generation join now (received when they arrived,
    // or now, waiting politely if the neighbour is a whole interval behind); also any that a
    // checkpoint held. This generation's leave without waiting for anyone.
    if (!settings_.async) receiveInFlight();
    joinArrived(pop, slots);
    sends_.post(outgoing_.data(), outgoing_.size(), PostedSends::Type::Uint32, right, kMigrationTag);
    if (!settings_.async) {
        inFlight_ = true;
        return;
    }
    // Async: take whatever has arrived.
    MPI_Status status;
    while (arrivedFrom(left, status)) {
        take(left, status, incoming_);
        if (unpack(incoming_, arrived_)) joinArrived(pop, slots);
    }
}

void RingMigration::receiveInFlight() {
    if (!inFlight_) return;
    inFlight_ = false;
    const int left = (mpi_.rank() + mpi_.size() - 1) % mpi_.size();
    MPI_Status status;
    politeProbe(mpi_, left, kMigrationTag, status);
    take(left, status, incoming_);
    unpack(incoming_, arrived_);
}

const Population& RingMigration::arrivals() {
    receiveInFlight();
    return arrived_;
}

void RingMigration::restoreArrivals(const Population& arrivals) {
    arrived_ = arrivals;
    inFlight_ = false;
}

void RingMigration::finish() {
    if (!mpi_.active() || mpi_.size() < 2) return;
    if (!settings_.async) {  // one message at most is in flight to each rank: take it, wait for ours
        receiveInFlight();
        politeWaitUntil(mpi_, [&] { return sends_.allComplete(); });
        return;
    }
    const int left = (mpi_.rank() + mpi_.size() - 1) % mpi_.size();
    drainUntilEveryoneIsDone(
        mpi_,
        [&] {  // late migrants are discarded
            MPI_Status status;
            if (!arrivedFrom(left, status)) return false;
            take(left, status, incoming_);
            return true;
        },
        [&] { return sends_.allComplete(); });
}

}  // namespace shapevo
