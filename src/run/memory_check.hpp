// Memory check of a new run: the search's estimate (search/memory_estimate.hpp) for every island
// on this machine against the memory the process may use, so that a population the machine
// cannot hold is refused (InputError, exit 2) before anything is created.
#pragma once
#include <cstdint>

#include "genome/genome_family.hpp"
#include "run/settings.hpp"

namespace shapevo {

/// What this process may use: physical memory (sysconf(_SC_PHYS_PAGES) x sysconf(_SC_PAGESIZE)),
/// lowered by a cgroup memory limit (v2 memory.max, v1 memory.limit_in_bytes; e.g. a Slurm
/// job's --mem) and by RLIMIT_AS where those are set. 0 if none is known.
std::uint64_t usableMemoryBytes();

/// @throw InputError(s.configPath, "ga.population", ...) with the estimate when `islands` islands
/// of `s` (the MPI ranks on this machine) searching `family`'s genomes need more than `available`
/// bytes (0 = unknown: no check).
void requireMemoryFits(const RunSettings& s, const GenomeFamily& family, int islands, std::uint64_t available);

}  // namespace shapevo
