// Scorer: the checking mode of incremental derivation (the rest of the interface is in the header).
#include "score/scorer.hpp"

#include <string>

#include "score/primitive_cache.hpp"

namespace shapevo {

void Scorer::checkDerivation(const Chromosome& c, ScoreWorkspace& w) const {
    const DeriveStatus status = derive(grammar(), c, w.checkGeometry, w.checkDerive, maxPrimitives_);  // no memo
    const auto& a = w.geometry.primitives;
    const auto& b = w.checkGeometry.primitives;
    std::size_t differ = a.size() == b.size() ? a.size() : 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        if (!(PrimitiveKey(a[i]) == PrimitiveKey(b[i]))) {
            differ = i;
            break;
        }
    if (status == w.status && a.size() == b.size() && differ == a.size() &&
        w.geometry.appearance == w.checkGeometry.appearance)
        return;
    throw IncrementalMismatch("incremental derivation differs from the full one: " + std::to_string(a.size()) +
                              " primitives against " + std::to_string(b.size()) + ", the first different one is #" +
                              std::to_string(differ) + ", status " + std::to_string(int(w.status)) + " against " +
                              std::to_string(int(status)));
}

}  // namespace shapevo
