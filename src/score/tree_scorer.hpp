// TreeScorer: the base of the scorers of the derivation-tree family (volume_scorer.hpp,
// image_scorer.hpp): it derives a chromosome with the scorer's Grammar into the workspace's
// geometry, counting what went wrong (deriveCounted), with the subtree memo's trial (kept on only
// where it is faster) and incremental scoring's checking mode. Only the time depends on the memo:
// the geometry and status are the same bit for bit.
#pragma once
#include "score/scorer.hpp"

namespace shapevo {

class TreeScorer : public Scorer {
public:
    /// The grammar this scorer derives with.
    virtual const Grammar& grammar() const = 0;

protected:
    /// Derives `c` into w.geometry and counts what went wrong; false: score kWorstFitness.
    bool deriveCounted(const Chromosome& c, ScoreWorkspace& w) const {
        if (w.derive.memo && w.derive.memo->on() && w.memoTrial < kMemoTrialEnd) [[unlikely]]
            w.status = deriveOnTrial(c, w);
        else
            w.status = derive(grammar(), c, w.geometry, w.derive, maxPrimitives());
        if (checksIncremental() && w.derive.memo) checkDerivation(c, w);
        if (w.status == DeriveStatus::Complete) [[likely]] return true;
        countAnomaly(w.status);
        return w.status != DeriveStatus::NonFinite;
    }

private:
    /// The memo's trial: after kMemoTrialStart derivations (a warm memo), every 8th of the next
    /// ones up to kMemoTrialEnd is derived both with and without the memo, timed; if the memo's
    /// total is the larger, it is turned off for this workspace. Only the time depends on it.
    static constexpr std::uint32_t kMemoTrialStart = 2048, kMemoTrialEnd = 3072;
    DeriveStatus deriveOnTrial(const Chromosome& c, ScoreWorkspace& w) const;
    /// Derive `c` again without the memo; throw IncrementalMismatch unless it gives w.geometry and w.status.
    void checkDerivation(const Chromosome& c, ScoreWorkspace& w) const;
};

}  // namespace shapevo
