// Ring migration: packing, validation, sync exchange with Isend/Irecv completed by politeWait,
// async with Isend/Iprobe.
#include "island/ring_migration.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <numeric>

#include <mpi.h>

#include "genome/validate.hpp"
#include "island/drain.hpp"
#include "island/polite_wait.hpp"

namespace shapevo {

namespace {
constexpr int kMigrationTag = 72;
}


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

std::string unpackIndividuals(const Grammar& g, const GenomeLimits& limits, const std::vector<std::uint32_t>& in,
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
        if (const std::string e = validateChromosome(g, c, limits); !e.empty()) return "individual " + std::to_string(k) + ": " + e;
        if (!std::isfinite(f)) return "individual " + std::to_string(k) + ": fitness is not finite";
        chromosomes.push_back(std::move(c));
        fitness.push_back(f);
    }
    return pos == in.size() ? "" : "trailing words";
}

std::vector<std::size_t> bestIndices(const Population& pop, std::size_t count) {
    std::vector<std::size_t> order(pop.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return pop.fitness[a] > pop.fitness[b]; });
    order.resize(std::min(count, order.size()));
    return order;
}

void replaceWorst(Population& pop, const std::vector<Chromosome>& arrivals, const std::vector<double>& fitness) {
    std::vector<std::size_t> order(pop.size());
    std::iota(order.begin(), order.end(), 0);
    // worst first; among equals the later index goes first, so the elite (early indices) stays
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return pop.fitness[a] < pop.fitness[b] || (pop.fitness[a] == pop.fitness[b] && a > b);
    });
    for (std::size_t k = 0; k < arrivals.size() && k < order.size(); ++k) {
        pop.individuals[order[k]] = arrivals[k];
        pop.fitness[order[k]] = fitness[k];
    }
}

RingMigration::RingMigration(const MpiSession& mpi, const MigrationSettings& settings, const Grammar& g,
                             const GenomeLimits& limits)
    : mpi_(mpi), settings_(settings), grammar_(g), limits_(limits) {}


void RingMigration::integrate(Population& pop, const std::vector<std::uint32_t>& words) {
    arrivals_.clear();
    arrivalFitness_.clear();
    const std::string problem = unpackIndividuals(grammar_, limits_, words, arrivals_, arrivalFitness_);
    if (!problem.empty()) {  // never let bad bytes into the population
        ++rejected_;
        return;
    }
    received_ += arrivals_.size();
    replaceWorst(pop, arrivals_, arrivalFitness_);
}

void RingMigration::afterGeneration(Population& pop, std::uint32_t generation) {
    if (!mpi_.active() || mpi_.size() < 2 || settings_.interval == 0 || settings_.count == 0) return;
    if (generation % settings_.interval != 0) return;
    const int right = (mpi_.rank() + 1) % mpi_.size(), left = (mpi_.rank() + mpi_.size() - 1) % mpi_.size();
    packIndividuals(pop, bestIndices(pop, settings_.count), outgoing_);
    if (!settings_.async) {
        // the exchange waits for the slower neighbour (politely: no busy core)
        int sendCount = int(outgoing_.size()), recvCount = 0;
        MPI_Request send, receive;
        MPI_Irecv(&recvCount, 1, MPI_INT, left, kMigrationTag, MPI_COMM_WORLD, &receive);
        MPI_Isend(&sendCount, 1, MPI_INT, right, kMigrationTag, MPI_COMM_WORLD, &send);
        politeWaitBoth(mpi_, send, receive);
        incoming_.resize(std::size_t(recvCount));
        MPI_Irecv(incoming_.data(), recvCount, MPI_UINT32_T, left, kMigrationTag, MPI_COMM_WORLD, &receive);
        MPI_Isend(outgoing_.data(), sendCount, MPI_UINT32_T, right, kMigrationTag, MPI_COMM_WORLD, &send);
        politeWaitBoth(mpi_, send, receive);
        integrate(pop, incoming_);
        return;
    }
    // Async: post this one, take whatever has arrived.
    sends_.post(outgoing_.data(), outgoing_.size(), PostedSends::Type::Uint32, right, kMigrationTag);
    for (;;) {
        int arrived = 0;
        MPI_Status status;
        MPI_Iprobe(left, kMigrationTag, MPI_COMM_WORLD, &arrived, &status);
        if (!arrived) break;
        int count = 0;
        MPI_Get_count(&status, MPI_UINT32_T, &count);
        incoming_.resize(std::size_t(count));
        MPI_Recv(incoming_.data(), count, MPI_UINT32_T, left, kMigrationTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        integrate(pop, incoming_);
    }
}

void RingMigration::finish() {
    if (!mpi_.active() || mpi_.size() < 2 || !settings_.async) return;
    const int left = (mpi_.rank() + mpi_.size() - 1) % mpi_.size();
    drainUntilEveryoneIsDone(
        mpi_,
        [&] {  // late migrants are discarded
            int arrived = 0;
            MPI_Status status;
            MPI_Iprobe(left, kMigrationTag, MPI_COMM_WORLD, &arrived, &status);
            if (!arrived) return false;
            int count = 0;
            MPI_Get_count(&status, MPI_UINT32_T, &count);
            incoming_.resize(std::size_t(count));
            MPI_Recv(incoming_.data(), count, MPI_UINT32_T, left, kMigrationTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            return true;
        },
        [&] { return sends_.allComplete(); });
}

}  // namespace shapevo
