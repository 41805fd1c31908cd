// CheckModels: the fixed sample of random models that start-up checks try before a run begins
// (run/scene.cpp: a grammar whose every model has a non-finite coordinate; the image kind: a
// camera that sees none of them). Models of the run's initial sizes, from a fixed seed, so a
// check is repeatable and every rank agrees. Any model family: its operators' random genomes.
#pragma once
#include <cstdint>

#include "genome/chromosome.hpp"
#include "genome/genome_family.hpp"
#include "genome/random.hpp"

namespace shapevo {

struct CheckModels {
    static constexpr int kCount = 64;  ///< models a check tries at most
    GenomeLimits limits;
    std::uint32_t initialGenesMin = 1, initialGenesMax = 1;  ///< ga.initial_genes_min / _max

    /// Give the models one by one to `f` until it returns true; returns whether it did.
    template <class F>
    bool any(const GenomeFamily& family, F&& f) const {
        Rng rng(12345);
        Chromosome c;
        const auto ops = family.makeOperators(limits);
        for (int i = 0; i < kCount; ++i) {
            ops->randomGenome(c, rng, initialGenesMin, initialGenesMax);
            if (f(c)) return true;
        }
        return false;
    }
};

}  // namespace shapevo
