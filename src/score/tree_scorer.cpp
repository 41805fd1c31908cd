// TreeScorer: the trial and the checking mode of incremental derivation (the rest is in the header).
#include "score/tree_scorer.hpp"

#include <chrono>
#include <string>

#include "score/primitive_cache.hpp"

namespace shapevo {

DeriveStatus TreeScorer::deriveOnTrial(const Chromosome& c, ScoreWorkspace& w) const {
    using Clock = std::chrono::steady_clock;
    const std::uint32_t n = ++w.memoTrial;
    if (n <= kMemoTrialStart || n % 8 != 0) return derive(grammar(), c, w.geometry, w.derive, maxPrimitives());
    // Alternately first and second: whichever runs second finds the chromosome in the cache.
    const bool memoFirst = n % 16 == 0;
    DeriveStatus status = DeriveStatus::Complete;
    const Clock::time_point t0 = Clock::now();
    if (memoFirst) status = derive(grammar(), c, w.geometry, w.derive, maxPrimitives());
    else derive(grammar(), c, w.checkGeometry, w.checkDerive, maxPrimitives());  // the same geometry, without
    const Clock::time_point t1 = Clock::now();
    if (memoFirst) derive(grammar(), c, w.checkGeometry, w.checkDerive, maxPrimitives());
    else status = derive(grammar(), c, w.geometry, w.derive, maxPrimitives());
    const Clock::time_point t2 = Clock::now();
    w.memoSeconds += std::chrono::duration<double>(memoFirst ? t1 - t0 : t2 - t1).count();
    w.plainSeconds += std::chrono::duration<double>(memoFirst ? t2 - t1 : t1 - t0).count();
    if (n == kMemoTrialEnd && w.memoSeconds > w.plainSeconds) w.derive.memo->turnOff();
    return status;
}

void TreeScorer::checkDerivation(const Chromosome& c, ScoreWorkspace& w) const {
    const DeriveStatus status = derive(grammar(), c, w.checkGeometry, w.checkDerive, maxPrimitives());  // no memo
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
