// The migration policy: who emigrates (the best) and who is replaced (the worst), with the ties
// broken by slot as migration_policy.hpp promises.
#include "search/migration_policy.hpp"

#include <algorithm>
#include <numeric>

namespace shapevo {

namespace {
/// Slots [first, last) in `out`, ordered by `before` (a strict total order: ties are broken by slot).
template <class Before>
void orderedSlots(std::size_t first, std::size_t last, std::size_t count, std::vector<std::size_t>& out, Before before) {
    out.resize(last > first ? last - first : 0);
    std::iota(out.begin(), out.end(), first);
    const std::size_t keep = std::min(count, out.size());
    std::partial_sort(out.begin(), out.begin() + std::ptrdiff_t(keep), out.end(), before);
    out.resize(keep);
}
}  // namespace

void selectEmigrants(std::span<const double> fitness, std::size_t first, std::size_t last, std::size_t count,
                     std::vector<std::size_t>& out) {
    orderedSlots(first, last, count, out, [&](std::size_t a, std::size_t b) {
        return fitness[a] > fitness[b] || (fitness[a] == fitness[b] && a < b);
    });
}

std::size_t bestEmigrant(std::span<const double> fitness, std::size_t first, std::size_t last) {
    std::size_t best = first;
    for (std::size_t i = first; i < last; ++i)
        if (fitness[i] > fitness[best]) best = i;  // strictly better: the lower slot stays among equals
    return best;
}

void selectReplaced(std::span<const double> fitness, std::size_t first, std::size_t last, std::size_t count,
                    std::vector<std::size_t>& out) {
    orderedSlots(first, last, count, out, [&](std::size_t a, std::size_t b) {
        return fitness[a] < fitness[b] || (fitness[a] == fitness[b] && a > b);
    });
}

std::size_t worstReplaced(std::span<const double> fitness, std::size_t first, std::size_t last) {
    std::size_t worst = first;
    for (std::size_t i = first; i < last; ++i)
        if (fitness[i] <= fitness[worst]) worst = i;  // not better: the higher slot wins among equals
    return worst;
}

std::vector<std::size_t> bestIndices(const Population& pop, std::size_t count) {
    std::vector<std::size_t> out;
    selectEmigrants(pop.fitness, 0, pop.size(), count, out);
    return out;
}

void replaceWorst(Population& pop, const std::vector<Chromosome>& arrivals, const std::vector<double>& fitness,
                  std::size_t slots) {
    std::vector<std::size_t> order;
    selectReplaced(pop.fitness, 0, std::min(slots, pop.size()), arrivals.size(), order);
    for (std::size_t k = 0; k < order.size(); ++k) {
        pop.individuals[order[k]] = arrivals[k];
        pop.fitness[order[k]] = fitness[k];
    }
}

}  // namespace shapevo
