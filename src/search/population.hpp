// Population: the individuals of one island and their fitness values.
#pragma once
#include <vector>

#include "genome/chromosome.hpp"

namespace shapevo {

struct Population {
    std::vector<Chromosome> individuals;
    std::vector<double> fitness;
    std::size_t size() const { return individuals.size(); }
    /// Index of the best individual (the lowest index among equals).
    std::size_t best() const {
        std::size_t b = 0;
        for (std::size_t i = 1; i < fitness.size(); ++i)
            if (fitness[i] > fitness[b]) b = i;
        return b;
    }
};

}  // namespace shapevo
